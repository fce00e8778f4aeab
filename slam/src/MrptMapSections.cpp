#include "omnirange_slam/MrptMapSections.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>
#include <mrpt/slam/CMetricMapBuilderRBPF.h>

#include <omnirange/config/OptionsTable.h>

#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>

namespace omnirange::slam
{
namespace
{
/** A config source over the user's file that notes every key read and the
 * default MRPT gave for it ("%.16e" for a double, "%i" for an int, "0"/"1"
 * for a bool). Sections and keys as MRPT matches them: in any case. */
class RecordingConfig : public mrpt::config::CConfigFileBase
{
   public:
	explicit RecordingConfig(const mrpt::config::CConfigFile& file) : file_(file) {}
	/** lower-case section -> lower-case key -> MRPT's default */
	std::map<std::string, std::map<std::string, std::string>> read;
	/** (section, key) MRPT requires: it ends with an error of its own without them. */
	std::vector<std::pair<std::string, std::string>> required;

	void getAllSections(std::vector<std::string>& s) const override { file_.getAllSections(s); }
	void getAllKeys(const std::string& s, std::vector<std::string>& k) const override { file_.getAllKeys(s, k); }
	void clear() override {}

   protected:
	void writeString(const std::string&, const std::string&, const std::string&) override {}
	std::string readString(const std::string& section, const std::string& name, const std::string& def,
						   bool fail) const override
	{
		auto* self = const_cast<RecordingConfig*>(this);
		self->read[lowercase(section)][lowercase(name)] = def;
		if (fail) self->required.emplace_back(section, name);  // said after reading, with the rest
		return file_.read_string(section, name, def, false);
	}

   private:
	const mrpt::config::CConfigFile& file_;
};

/** The names of an enum MRPT reads with read_enum, in order (their numbers), where known. */
std::vector<std::string> knownEnum(const std::string& lower_key)
{
	if (lower_key == "pf_algorithm")
		return {"pfStandardProposal", "pfAuxiliaryPFStandard", "pfOptimalProposal", "pfAuxiliaryPFOptimal"};
	if (lower_key == "resamplingmethod") return {"prMultinomial", "prResidual", "prStratified", "prSystematic"};
	if (lower_key == "verbosity_level") return {"DEBUG", "INFO", "WARN", "ERROR"};
	return {};
}

/** A key's own range, where MRPT asserts one at run time or past which a
 * grid or a filter outgrows the memory before the program says a word. */
struct KeyRange
{
	const char* key;  // lower case
	double lo, hi;
	bool lo_open, hi_open;
	const char* says;
};
constexpr double kNoEnd = std::numeric_limits<double>::infinity();
constexpr KeyRange kKeyRanges[] = {
	// Closer to 1, ICP shrinks its thresholds so slowly that it seems to hang (0.999999: two minutes for 20 scans).
	{"alfa", 0, 0.99, false, false, "must be within [0, 0.99] (MRPT asserts below 1; nearer 1 a match takes minutes)"},
	{"corresponding_points_decimation", 1, kNoEnd, false, false, "must be >= 1"},
	{"resolution", 0.005, 10, false, false, "must be within [0.005, 10] m"},
	{"min_x", -1000, 1000, false, false, "must be within [-1000, 1000] m"},
	{"max_x", -1000, 1000, false, false, "must be within [-1000, 1000] m"},
	{"min_y", -1000, 1000, false, false, "must be within [-1000, 1000] m"},
	{"max_y", -1000, 1000, false, false, "must be within [-1000, 1000] m"},
	{"samplesize", 1, 1e4, false, false, "must be within [1, 10000]"},
	{"kld_minsamplesize", 1, 1e4, false, false, "must be within [1, 10000]"},
	{"kld_maxsamplesize", 1, 1e5, false, false, "must be within [1, 100000]"},
	{"kld_binsize_xy", 0, kNoEnd, true, false, "must be > 0"},
	{"kld_binsize_phi", 0, kNoEnd, true, false, "must be > 0"},
	{"maxoccupancyupdatecertainty", 0.5, 1, false, true, "must be within [0.5, 1)"},
	{"maxdistanceinsertion", 0, kNoEnd, true, false, "must be > 0 m (a map that takes no point is empty)"},
	{"minicpgoodnesstoaccept", 0, 1, false, false, "must be within [0, 1]"},
};

/** A map count (NAME_count): MRPT makes that many maps' options. */
bool isMapCount(const std::string& lower_key)
{
	return lower_key.size() > 6 && lower_key.compare(lower_key.size() - 6, 6, "_count") == 0;
}
}  // namespace

void requireLikeMrptsDefault(const std::string& key, const std::string& model, const std::string& value,
							 const MrptValueBounds& bounds)
{
	const std::string k = lowercase(key);
	if (model == "true" || model == "false")
	{
		parseBool(value);
		return;
	}
	const bool numeric = !model.empty() && (std::isdigit(static_cast<unsigned char>(model[0])) || model[0] == '-' ||
											 model[0] == '+' || model[0] == '.');
	if (!numeric)  // an enum: its name, or (as MRPT's read_enum takes it) its number
	{
		const auto names = knownEnum(k);
		if (!names.empty())
		{
			for (std::size_t i = 0; i < names.size(); ++i)
				if (value == names[i] || value == std::to_string(i)) return;
			throw std::invalid_argument("must be one of " + joined(names) + " (or its number, from 0)");
		}
		if (value.empty() || value.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_0123456789") !=
								 std::string::npos)
			throw std::invalid_argument("not a name like '" + model + "'");
		return;
	}
	double v = 0;
	if (model == "0" || model == "1")  // a bool as MRPT writes it ("%i"), or an int of 0 or 1
		try
		{
			parseBool(value);
			return;
		}
		catch (const std::invalid_argument&)
		{
			try
			{
				v = parseDouble(value);
			}
			catch (const std::invalid_argument&)
			{
				throw std::invalid_argument("must be true or false (or a whole number)");
			}
		}
	else
		v = parseDouble(value);
	// MRPT reads a whole number with atoi: '8e1' and '8.0' are 8 and 8 there, whatever they are here.
	if (model.find_first_of(".eE") == std::string::npos &&
		(value.find_first_not_of("-0123456789") != std::string::npos || value.find('-', 1) != std::string::npos))
		throw std::invalid_argument("not a whole number written in digits (MRPT would read '" + value + "' as " +
									std::to_string(std::atoi(value.c_str())) + ")");
	// As MRPT keeps most of its options, a float: 0.99999999999 is 1 there, and so is each bound compared.
	const auto f = [](double x) { return static_cast<double>(static_cast<float>(x)); };
	for (const auto& r : kKeyRanges)
		if (k == r.key &&
			!((r.lo_open ? f(v) > f(r.lo) : f(v) >= f(r.lo)) && (r.hi_open ? f(v) < f(r.hi) : f(v) <= f(r.hi))))
			throw std::invalid_argument(r.says);
	if (isMapCount(k) && !(v >= 0 && v <= 16)) throw std::invalid_argument("must be within [0, 16]");
	if (bounds.keep_sign && model[0] != '-' && v < 0) throw std::invalid_argument("must be >= 0");
	parseWithin(value, bounds.largest);
}

namespace
{
/** Map and filter values: no sign rule (an extent may lie anywhere), and no
 * value past a million of anything. */
constexpr MrptValueBounds kMapValueBounds{1e6, false};

/** [cells] The largest grid a map section may make: 10^8 cells, 10 km by 10 km
 * at 1 m or 500 m square at 5 cm, are a couple of hundred megabytes already. */
constexpr double kMaxGridCells = 1e8;

/** A grid's extent over its resolution, from the section's values or MRPT's
 * defaults: each within its bounds, the whole still too big to allocate. */
void requireGridSize(const mrpt::config::CConfigFile& ini, const std::string& section,
					 const std::map<std::string, std::string>& read)
{
	if (!read.count("resolution") || !read.count("min_x")) return;  // not a grid's creation options
	const auto value = [&](const char* key) {
		const std::string text = trimmed(ini.read_string(section, key, read.at(key)));
		try
		{
			return parseDouble(text);
		}
		catch (const std::invalid_argument&)
		{
			return 0.0;  // said with the key's name by the key's own check
		}
	};
	const double res = value("resolution"), w = value("max_x") - value("min_x"), h = value("max_y") - value("min_y");
	if (res > 0 && (w / res) * (h / res) > kMaxGridCells)
		throw std::invalid_argument("[" + section + "] a grid of " + formatDouble(std::round(w)) + " m by " +
									formatDouble(std::round(h)) + " m at " + formatDouble(std::round(res * 1e4) / 1e4) + " m is " +
									formatDouble(std::round(w / res * h / res / 1e6)) +
									" million cells, more than 100 million: make the resolution coarser or the extent smaller");
}

/** Every section of `ini` that `inScope` takes is one MRPT read from
 * `recording` (or [MappingApplication], whose keys MRPT did not read are the
 * program's own: checked by `programKey`), each key one it read, each value
 * of its default's kind. */
void requireRecorded(const mrpt::config::CConfigFile& ini, RecordingConfig& recording,
					 const std::function<bool(const std::string&)>& inScope,
					 const std::function<void(const std::string&)>& programKey)
{
	for (const auto& [section, key] : recording.required)
		if (!ini.keyExists(section, key))
			throw std::invalid_argument("[" + section + "] " + key + " is missing: MRPT requires it here");
	std::vector<std::string> sections;
	ini.getAllSections(sections);
	for (const auto& s : sections)
	{
		const std::string ls = lowercase(s);
		if (!inScope(ls)) continue;
		const bool app = ls == "mappingapplication";
		// icp-slam's own sections, in the ini of another program: most likely the wrong file was named.
		const bool icp = ls == "icp" || ls == "odometry_guard" || ls == "loop_closure";
		if (!app && recording.read.count(ls) == 0)
			throw std::invalid_argument("unknown section [" + s + "]: MRPT reads no such section here " +
										(icp ? "(it is an icp-slam ini's: is this the file meant?)"
											 : "(misspelt, or past its map's count?)"));
		const auto& read = recording.read[ls];
		std::vector<std::string> keys;
		ini.getAllKeys(s, keys);
		for (const auto& key : keys)
		{
			const auto model = read.find(lowercase(key));
			if (model == read.end() && app)
			{
				programKey(key);
				continue;
			}
			if (model == read.end()) throw std::invalid_argument("[" + s + "] " + key + ": not a key MRPT reads (misspelt?)");
			const std::string value = trimmed(ini.read_string(s, key, ""));
			try
			{
				requireLikeMrptsDefault(key, model->second, value, kMapValueBounds);
			}
			catch (const std::invalid_argument& e)
			{
				throw std::invalid_argument("[" + s + "] " + key + " = '" + value + "': " + e.what());
			}
		}
		requireGridSize(ini, s, read);  // each value within its bounds, the whole grid too
	}
}

/** The map counts in [`section`], checked before MRPT reads them: MRPT makes
 * that many maps' options, and -1 (read as an unsigned count) never ends. */
void requireMapCounts(const mrpt::config::CConfigFile& ini, const std::string& section)
{
	std::vector<std::string> keys;
	ini.getAllKeys(section, keys);
	for (const auto& key : keys)
		if (isMapCount(lowercase(key)))
			try
			{
				requireLikeMrptsDefault(key, "0", trimmed(ini.read_string(section, key, "")), kMapValueBounds);
			}
			catch (const std::invalid_argument& e)
			{
				throw std::invalid_argument("[" + section + "] " + key + " = '" + trimmed(ini.read_string(section, key, "")) +
											"': " + e.what());
			}
}

/** Runs `check` on the ini `file`, its errors one line naming the file. */
void namingTheFile(const std::string& file, const std::function<void()>& check)
{
	try
	{
		requireNoRepeatedKeys(file);
		requireMapCounts(mrpt::config::CConfigFile(file), "MappingApplication");
		check();
	}
	catch (const std::exception& e)
	{
		const std::string what = e.what();
		throw std::runtime_error(what.rfind(file, 0) == 0 ? what : file + ": " + what);
	}
}

/** A key of the app's own in [MappingApplication]: one of `known` (any case). */
std::function<void(const std::string&)> oneOf(const std::vector<std::string>& known, const std::string& program)
{
	return [known, program](const std::string& key) {
		for (const auto& k : known)
			if (sameKey(k, key)) return;
		throw std::invalid_argument("[MappingApplication] " + key + ": not a key " + program + " reads (misspelt?)");
	};
}
}  // namespace

void requireStrictMapSections(const std::string& file, const std::string& prefix)
{
	namingTheFile(file, [&] {
		const mrpt::config::CConfigFile ini(file);
		RecordingConfig recording(ini);
		mrpt::maps::TSetOfMetricMapInitializers maps;
		maps.loadFromConfigFile(recording, prefix);
		// icp-slam's map builder reads its own keys there too (minICPgoodnessToAccept, ...): their values are checked alike.
		mrpt::system::VerbosityLevel level = mrpt::system::LVL_INFO;
		mrpt::slam::CMetricMapBuilderICP::TConfigParams(level).loadFromConfigFile(recording, prefix);
		const std::string p = lowercase(prefix);
		requireRecorded(
			ini, recording, [&](const std::string& s) { return s == p || s.rfind(p + "_", 0) == 0; },
			[](const std::string&) {});  // the program's own keys: its caller checks them
	});
}

void requireStrictObservationsToMapIni(const std::string& file)
{
	namingTheFile(file, [&] {
		const mrpt::config::CConfigFile ini(file);
		RecordingConfig recording(ini);
		mrpt::maps::TSetOfMetricMapInitializers maps;
		maps.loadFromConfigFile(recording, "MappingApplication");
		requireRecorded(ini, recording, [](const std::string&) { return true; },
						oneOf({}, "observations2map"));
	});
}

void requireStrictRbpfIni(const std::string& file)
{
	namingTheFile(file, [&] {
		const mrpt::config::CConfigFile ini(file);
		RecordingConfig recording(ini);
		mrpt::slam::CMetricMapBuilderRBPF::TConstructionOptions options;
		options.loadFromConfigFile(recording, "MappingApplication");
		// rbpf-slam's own keys (MRPT 2.5.8, apps/src/RBPF_SLAM_App.cpp).
		requireRecorded(ini, recording, [](const std::string&) { return true; },
						oneOf({"rawlog_offset", "logOutput_dir", "LOG_FREQUENCY", "GENERATE_LOG_JOINT_H",
							   "GENERATE_LOG_INFO", "SAVE_MAP_IMAGES", "SAVE_3D_SCENE", "SAVE_POSE_LOG",
							   "SAVE_ENOSE_READINGS", "CAMERA_3DSCENE_FOLLOWS_ROBOT", "SHOW_PROGRESS_IN_WINDOW",
							   "PROGRESS_WINDOW_WIDTH", "PROGRESS_WINDOW_HEIGHT", "RANDOM_SEED",
							   "SHOW_PROGRESS_3D_REAL_TIME"},
							  "rbpf-slam"));
	});
}

}  // namespace omnirange::slam
