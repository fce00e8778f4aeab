#include "omnirange_slam/IcpSlamIni.h"
#include "omnirange_slam/MrptMapSections.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/slam/CICP.h>

#include <omnirange/config/OptionsTable.h>

#include <algorithm>
#include <map>
#include <filesystem>
#include <stdexcept>

namespace omnirange::slam
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
		// MRPT matches keys in any case (maxiterations is maxIterations).
		if (std::none_of(known.begin(), known.end(), [&](const std::string& m) { return sameKey(k, m); }))
			ignored.push_back(k);
	std::sort(ignored.begin(), ignored.end());
	return ignored;
}

namespace
{
/** ICP's values: past 1e4 MRPT's squared distances overflow and matching
 * runs without end (thresholdDist = 1e200). */
constexpr MrptValueBounds kIcpValueBounds{1e4, true};

/** The keys MRPT 2.5.8 reads from icp-slam's [MappingApplication]: the app's
 * own (libs/apps/src/ICP_SLAM_App.cpp), the map builder's
 * (CMetricMapBuilderICP::TConfigParams) and one `NAME_count` per map kind
 * MRPT has registered (TSetOfMetricMapInitializers). */
bool mrptReadsMappingKey(const std::string& key)
{
	static const char* const known[] = {
		"rawlog_file", "rawlog_offset", "logOutput_dir", "LOG_FREQUENCY", "SAVE_POSE_LOG", "SAVE_3D_SCENE",
		"CAMERA_3DSCENE_FOLLOWS_ROBOT", "SHOW_PROGRESS_3D_REAL_TIME", "SHOW_PROGRESS_3D_REAL_TIME_DELAY_MS",
		"SHOW_LASER_SCANS_3D", "verbosity", "alwaysInsertByClass", "matchAgainstTheGrid", "insertionLinDistance",
		"insertionAngDistance", "localizationLinDistance", "localizationAngDistance", "verbosity_level",
		"minICPgoodnessToAccept"};
	for (const char* k : known)
		if (sameKey(key, k)) return true;  // MRPT matches keys in any case
	const std::string suffix = "_count";
	if (key.size() <= suffix.size() || key.compare(key.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
	const auto& kinds = mrpt::maps::internal::TMetricMapTypesRegistry::Instance().getAllRegistered();
	return kinds.count(key.substr(0, key.size() - suffix.size())) > 0;
}
}  // namespace

void requireStrictIcpSection(const std::string& file, const std::string& section)
{
	try
	{
		requireNoRepeatedKeys(file);
		// A misspelt section ([IPC], [odometry_gaurd]) would leave its keys unread.
		std::vector<std::string> sections;
		mrpt::config::CConfigFile(file).getAllSections(sections);
		for (const auto& s : sections)
			if (s != "MappingApplication" && s.rfind("MappingApplication_", 0) != 0 && s != section &&
				s != "odometry_guard" && s != "loop_closure")
				throw std::invalid_argument("unknown section [" + s + "] (an icp-slam ini has [MappingApplication] and "
											"its map sections, [" + section + "], [odometry_guard] and [loop_closure])");
		std::vector<std::string> mapping_keys;
		mrpt::config::CConfigFile(file).getAllKeys("MappingApplication", mapping_keys);
		for (const auto& k : mapping_keys)
			if (!mrptReadsMappingKey(k))
				throw std::invalid_argument("[MappingApplication] " + k + ": not a key icp-slam reads (misspelt?)");
		if (mrpt::config::CConfigFile(file).keyExists("MappingApplication", "logOutput_dir")) mrptLogFolder(file);
		requireStrictMapSections(file);
		if (!mrpt::config::CConfigFile(file).sectionExists(section)) return;  // every option at MRPT's default
		for (const auto& k : icpKeysMrptIgnores(file, section))
			throw std::invalid_argument("[" + section + "] " + k + ": not a key MRPT reads (it would keep its default)");
		// Each value of the kind of MRPT's own default for the key.
		mrpt::config::CConfigFileMemory written;
		mrpt::slam::CICP::TConfigParams().saveToConfigFile(written, section);
		std::map<std::string, std::string> defaults;  // key as read -> MRPT's default, as written
		std::vector<std::string> padded;
		written.getAllKeys(section, padded);
		for (const auto& k : padded) defaults[lowercase(trimmed(k))] = trimmed(written.read_string(section, k, "", false));
		const mrpt::config::CConfigFile ini(file);
		std::vector<std::string> keys;
		ini.getAllKeys(section, keys);
		for (const auto& key : keys)
		{
			std::string as_written = lowercase(key);
			if (as_written.size() > 4 && as_written.compare(as_written.size() - 4, 4, "_deg") == 0)
				as_written.resize(as_written.size() - 4);
			const std::string model = defaults[as_written];
			const std::string value = readRawValue(ini, section, key);
			try
			{
				requireLikeMrptsDefault(as_written, model, value, kIcpValueBounds);
			}
			catch (const std::invalid_argument& e)
			{
				throw std::invalid_argument("[" + section + "] " + key + " = '" + value + "': " + e.what());
			}
		}
	}
	catch (const std::exception& e)
	{
		const std::string what = e.what();
		throw std::runtime_error(what.rfind(file, 0) == 0 ? what : file + ": " + what);
	}
}

std::string mrptLogFolder(const std::string& file)
{
	// MRPT's apps read it with no default: a missing key ends them with an error of their own.
	const std::string dir = trimmed(mrpt::config::CConfigFile(file).read_string("MappingApplication", "logOutput_dir", ""));
	if (dir.empty() || dir.find('/') != std::string::npos || dir == "." || dir == "..")
		throw std::runtime_error(file + ": [MappingApplication] logOutput_dir = '" + dir +
								 "': MRPT's program empties this folder first, so it must be a plain folder name "
								 "(no '/', not '.' or '..'), made where the program runs");
	return dir;
}

std::vector<std::string> mappingSettingsGuardedIcpIgnores(const std::string& file)
{
	const mrpt::config::CConfigFile ini(file);
	const auto value = [&](const char* key, const char* fallback) {
		return trimmed(ini.read_string("MappingApplication", key, fallback));
	};
	std::vector<std::string> ignored;
	if (parseDouble(value("rawlog_offset", "0")) != 0) ignored.push_back("rawlog_offset = " + value("rawlog_offset", ""));
	if (parseBool(value("matchAgainstTheGrid", "false"))) ignored.push_back("matchAgainstTheGrid = " + value("matchAgainstTheGrid", ""));
	if (parseDouble(value("pointsMap_count", "1")) != 1) ignored.push_back("pointsMap_count = " + value("pointsMap_count", ""));
	return ignored;
}

}  // namespace omnirange::slam
