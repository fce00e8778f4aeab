#include "omnirange_eval/IcpSlamIni.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/slam/CICP.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace omnirange::eval
{
std::vector<std::string> icpKeysMrptIgnores(const std::string& file, const std::string& section)
{
	if (!std::filesystem::is_regular_file(file)) throw std::runtime_error("cannot read icp-slam ini '" + file + "'");
	// The keys the options write are the keys they read, but for the two
	// angles: written in radians as thresholdAng and ransac_fuseMaxDiffPhi,
	// read in degrees with the suffix _DEG.
	mrpt::config::CConfigFileMemory written;
	mrpt::slam::CICP::TConfigParams().saveToConfigFile(written, section);
	std::vector<std::string> known;
	written.getAllKeys(section, known);
	for (auto& k : known)
	{
		k.erase(k.find_last_not_of(' ') + 1);  // written keys are padded
		if (k == "thresholdAng" || k == "ransac_fuseMaxDiffPhi") k += "_DEG";
	}

	const mrpt::config::CConfigFile ini(file);
	if (!ini.sectionExists(section))
		throw std::runtime_error("icp-slam ini '" + file + "' has no [" + section + "] section: icp-slam would run with every ICP option at its default");
	std::vector<std::string> keys, ignored;
	ini.getAllKeys(section, keys);
	for (const auto& k : keys)
		if (std::find(known.begin(), known.end(), k) == known.end()) ignored.push_back(k);
	std::sort(ignored.begin(), ignored.end());
	return ignored;
}

}  // namespace omnirange::eval
