#include "omnirange_eval/Suite.h"

#include <omnirange/config/OptionsTable.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace omnirange::eval
{
std::vector<SuiteEntry> loadSuite(const std::string& path)
{
	std::vector<SuiteEntry> suite;
	forEachDataLine(path, "experiment list", [&](int, const std::string& line) {
		std::istringstream in(line);
		SuiteEntry e;
		if (!(in >> e.name >> e.group)) throw std::invalid_argument("expected 'NAME GROUP WHAT'");
		std::getline(in, e.description);
		e.description = trimmed(e.description);
		for (const auto& seen : suite)
			if (seen.name == e.name) throw std::invalid_argument("'" + e.name + "' is listed twice");
		suite.push_back(e);
	});
	return suite;
}

}  // namespace omnirange::eval
