#include "omnirange_slam/MrptMapSections.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/TMetricMapInitializer.h>

#include <omnirange/config/OptionsTable.h>

#include <cctype>
#include <cmath>
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

	void getAllSections(std::vector<std::string>& s) const override { file_.getAllSections(s); }
	void getAllKeys(const std::string& s, std::vector<std::string>& k) const override { file_.getAllKeys(s, k); }
	void clear() override {}

   protected:
	void writeString(const std::string&, const std::string&, const std::string&) override {}
	std::string readString(const std::string& section, const std::string& name, const std::string& def,
						   bool fail) const override
	{
		const_cast<RecordingConfig*>(this)->read[lowercase(section)][lowercase(name)] = def;
		return file_.read_string(section, name, def, fail);
	}

   private:
	const mrpt::config::CConfigFile& file_;
};

/** The value checked against the kind of MRPT's default. */
void requireLikeDefault(const std::string& key, const std::string& model, const std::string& value)
{
	const std::string k = lowercase(key);
	const bool numeric = !model.empty() && (std::isdigit(static_cast<unsigned char>(model[0])) || model[0] == '-' ||
											 model[0] == '+' || model[0] == '.');
	if (!numeric)  // an enum's name, as MRPT's default is
	{
		if (value.empty() || value.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_0123456789") !=
								 std::string::npos)
			throw std::invalid_argument("not a name like '" + model + "'");
		return;
	}
	double v = 0;
	if (model == "0" || model == "1")  // a bool, or an int of 0 or 1
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
	const bool whole = model.find_first_of(".eE") == std::string::npos;
	if (whole && v != std::floor(v)) throw std::invalid_argument("not a whole number");
	if (k.size() > 6 && k.compare(k.size() - 6, 6, "_count") == 0 && !(v >= 0 && v <= 16))
		throw std::invalid_argument("must be within [0, 16]");
	if (k == "resolution" && !(v > 0)) throw std::invalid_argument("must be > 0");
	if (k == "maxoccupancyupdatecertainty" && !(v >= 0.5 && v < 1)) throw std::invalid_argument("must be within [0.5, 1)");
	if (std::abs(v) > 1e6) throw std::invalid_argument("must be within [-1e6, 1e6]");
}
}  // namespace

void requireStrictMapSections(const std::string& file, const std::string& prefix)
{
	try
	{
		const mrpt::config::CConfigFile ini(file);
		RecordingConfig recording(ini);
		mrpt::maps::TSetOfMetricMapInitializers maps;
		maps.loadFromConfigFile(recording, prefix);
		std::vector<std::string> sections;
		ini.getAllSections(sections);
		const std::string lower_prefix = lowercase(prefix);
		for (const auto& s : sections)
		{
			const std::string ls = lowercase(s);
			const bool counts = ls == lower_prefix;
			if (!counts && ls.rfind(lower_prefix + "_", 0) != 0) continue;  // not a map's
			if (!counts && recording.read.count(ls) == 0)
				throw std::invalid_argument("unknown section [" + s + "]: no map of [" + prefix +
											"]'s counts reads it (misspelt, or past its map's count?)");
			const auto& read = recording.read[ls];
			std::vector<std::string> keys;
			ini.getAllKeys(s, keys);
			for (const auto& key : keys)
			{
				const auto model = read.find(lowercase(key));
				if (model == read.end() && counts) continue;  // the program's own keys, checked by it
				if (model == read.end())
					throw std::invalid_argument("[" + s + "] " + key + ": not a key MRPT reads (misspelt?)");
				const std::string value = trimmed(ini.read_string(s, key, ""));
				try
				{
					requireLikeDefault(key, model->second, value);
				}
				catch (const std::invalid_argument& e)
				{
					throw std::invalid_argument("[" + s + "] " + key + " = '" + value + "': " + e.what());
				}
			}
		}
	}
	catch (const std::exception& e)
	{
		const std::string what = e.what();
		throw std::runtime_error(what.rfind(file, 0) == 0 ? what : file + ": " + what);
	}
}

}  // namespace omnirange::slam
