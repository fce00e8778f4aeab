#include "omnirange/Config.h"

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <stdexcept>

namespace omnirange
{
void requireKnownKeys(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::vector<std::string>& known)
{
	std::vector<std::string> present;
	cfg.getAllKeys(section, present);
	for (const auto& k : present)
		if (std::find(known.begin(), known.end(), k) == known.end())
			throw std::invalid_argument(
				"unknown key '" + k + "' in section [" + section + "]");
}

void requireParam(bool ok, const std::string& section, const std::string& what)
{
	if (!ok) throw std::invalid_argument("[" + section + "] " + what);
}

}  // namespace omnirange
