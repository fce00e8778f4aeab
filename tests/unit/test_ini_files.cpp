// The shipped ini files load, carry the paper's Table I, document every key
// with a unit; docs/parameters.md lists every key with the code's default.
#include "SyntheticOmni.h"

#include <omnirange/core/Rangefinder.h>
#include <omnirange/train/ParameterLearning.h>
#include <omnirange/config/LayeredIni.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

using namespace omnirange;

namespace
{
const std::string kSource = OMNIRANGE_SOURCE_DIR;

RangefinderParams loadIni(const std::string& name)
{
	return RangefinderParams::loadFromFile(kSource + "/ini/" + name, "rangefinder");
}

std::vector<std::string> lines(const std::string& path)
{
	std::ifstream f(path);
	EXPECT_TRUE(f.good()) << path;
	std::vector<std::string> out;
	for (std::string l; std::getline(f, l);) out.push_back(l);
	return out;
}
}  // namespace

TEST(IniFiles, MazeAndFactoryCarryTableI)
{
	const RangefinderParams maze = loadIni("maze.ini");
	EXPECT_EQ(maze.scanner.filter.N, 20);
	EXPECT_EQ(maze.scanner.filter.K, 2);
	EXPECT_DOUBLE_EQ(maze.threshold, 0.05);
	const RangefinderParams factory = loadIni("factory.ini");
	EXPECT_EQ(factory.scanner.filter.N, 20);
	EXPECT_EQ(factory.scanner.filter.K, 2);
	EXPECT_DOUBLE_EQ(factory.threshold, 0.075);
	for (const auto* p : {&maze, &factory})
	{
		EXPECT_EQ(p->scanner.scanlines, 360);
		EXPECT_DOUBLE_EQ(p->scanner.max_range, 3.8);
		EXPECT_DOUBLE_EQ(p->camera.R, 192);
		EXPECT_DOUBLE_EQ(p->camera.h, 0.931);
		EXPECT_NO_THROW(Rangefinder(*p, test::floorHistogram()));
	}
}

TEST(IniFiles, EveryKeyHasAUnitComment)
{
	const std::regex key(R"(^\s*([A-Za-z_][A-Za-z0-9_]*)\s*=)");
	const std::regex unit(R"(^\s*;.*\[[^\]]+\])");
	for (const auto& entry : std::filesystem::directory_iterator(kSource + "/ini"))
	{
		const std::string name = entry.path().filename().string();
		const auto ls = lines(entry.path().string());
		std::string last_unit_comment;
		bool has_unit = false;
		for (const auto& l : ls)
		{
			std::smatch m;
			if (std::regex_search(l, unit)) has_unit = true;
			else if (std::regex_search(l, m, key))
				EXPECT_TRUE(has_unit) << name << ": key '" << m[1] << "' has no [unit] comment";
			else if (l.empty() || l[0] == '[')
				has_unit = false;  // a unit comment covers only the keys right below it
		}
	}
}

TEST(IniFiles, AnExperimentIniRepeatsNoKeyOfItsBaseAndTheBaseNoDefault)
{
	// One fact in one place: a key an experiment sets to its base's value, or
	// a key the base sets to the code's default, is a copy that can drift.
	const auto keysOf = [](const std::string& path) {
		mrpt::config::CConfigFile f(path);
		std::map<std::string, std::string> m;  // "[section] key" -> value
		std::vector<std::string> sections, keys;
		f.getAllSections(sections);
		for (const auto& s : sections)
		{
			f.getAllKeys(s, keys);
			for (const auto& k : keys)
				if (!s.empty()) m["[" + s + "] " + k] = f.read_string(s, k, "", true);
		}
		return m;
	};
	int experiments = 0;
	for (const auto& entry : std::filesystem::directory_iterator(kSource + "/ini"))
	{
		const std::string base = iniBaseOf(entry.path().string());
		if (base.empty()) continue;
		++experiments;
		const auto own = keysOf(entry.path().string()), inherited = keysOf(base);
		for (const auto& [key, value] : own)
		{
			EXPECT_FALSE(inherited.count(key) && inherited.at(key) == value)
				<< entry.path().filename() << " repeats " << key << " = " << value << " of its base";
		}
	}
	EXPECT_GE(experiments, 2);
	const auto same = [](const std::string& a, const std::string& b) {
		char *ea = nullptr, *eb = nullptr;
		const double da = std::strtod(a.c_str(), &ea), db = std::strtod(b.c_str(), &eb);
		return (*ea == 0 && *eb == 0 && ea != a.c_str()) ? da == db : a == b;
	};
	const auto base = keysOf(kSource + "/ini/experiment-base.ini");
	const RangefinderParams defaults;
	for (const auto& f : RangefinderParams::table().fields())
	{
		const auto it = base.find("[rangefinder] " + f.info.key);
		if (it == base.end()) continue;
		EXPECT_FALSE(same(it->second, f.print(defaults))) << "experiment-base.ini repeats the default " << it->first;
	}
	int base_keys = 0;
	for (const auto& [key, value] : base) base_keys += key.rfind("[rangefinder] ", 0) == 0;
	EXPECT_GE(base_keys, 1);
}

namespace
{
struct DocumentedKey
{
	std::string unit, default_value, values;
};

/** Every key of `table` has its row in docs/parameters.md, with the code's unit, default and range. */
template <class S>
void expectDocumented(const OptionsTable<S>& table, std::map<std::string, DocumentedKey>& documented)
{
	const S defaults;
	for (const auto& f : table.fields())
	{
		ASSERT_TRUE(documented.count(f.info.key)) << "docs/parameters.md lacks '" << f.info.key << "'";
		const DocumentedKey& doc = documented[f.info.key];
		EXPECT_EQ(doc.unit, f.info.unit) << f.info.key;
		const std::string code = f.print(defaults);
		char* end = nullptr;
		const double dv = std::strtod(doc.default_value.c_str(), &end);
		if (end != doc.default_value.c_str() && code.find(' ') == std::string::npos)  // a number, not a list
			EXPECT_NEAR(dv, std::stod(code), 1e-5 * std::max(1.0, std::abs(dv))) << f.info.key;
		else
			EXPECT_EQ(doc.default_value, code) << f.info.key;
		// The values: the table's range (the docs may add what other keys bound), an enum's every name.
		if (f.info.range)
		{
			EXPECT_EQ(doc.values.rfind(f.info.range->text(), 0), 0u)
				<< f.info.key << ": '" << doc.values << "' should begin with '" << f.info.range->text() << "'";
		}
		std::string names;
		for (const auto& c : f.info.choices) names += (names.empty() ? "" : ", ") + c;
		if (!names.empty())
		{
			EXPECT_EQ(doc.values, names) << f.info.key;
		}
	}
}
}  // namespace

TEST(IniFiles, DocsListEveryKeyWithTheCodesUnitAndDefault)
{
	const std::regex row(R"(^\|\s*`([A-Za-z_][A-Za-z0-9_]*)`\s*\|\s*([^|]*?)\s*\|\s*([^|]*?)\s*\|\s*((?:[^|\\]|\\.)*?)\s*\|)");
	std::map<std::string, DocumentedKey> documented;
	for (const auto& l : lines(kSource + "/docs/parameters.md"))
	{
		std::smatch m;
		if (std::regex_search(l, m, row)) documented[m[1]] = {m[2], m[3], m[4]};
	}
	expectDocumented(RangefinderParams::table(), documented);
	expectDocumented(TrainingParams::table(), documented);
	expectDocumented(LearningOptions::table(), documented);
	EXPECT_EQ(documented.size(), RangefinderParams::table().fields().size() + TrainingParams::table().fields().size() +
									 LearningOptions::table().fields().size());
}
