#pragma once
// What the in-process tests share: the factory sample, its ini, a fresh
// folder per test, a file's text, what a call throws.

#include <omnirange/core/Rangefinder.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>

namespace omnirange::test
{
const std::string kSource = OMNIRANGE_SOURCE_DIR;
const std::string kSample = kSource + "/rawlogs/factory-sample.rawlog";
const std::string kIni = kSource + "/ini/factory.ini";

/** An empty folder TMP/`group`/`name`. */
inline std::string freshDir(const std::string& group, const std::string& name)
{
	const auto d = std::filesystem::temp_directory_path() / group / name;
	std::filesystem::remove_all(d);
	std::filesystem::create_directories(d);
	return d.string();
}

/** kIni and its base as one [rangefinder] section with every key written
 * out: for tests that edit an ini's text or copy it where its base is not. */
inline std::string factoryIniText()
{
	return "[rangefinder]\n" + RangefinderParams::loadFromFile(kIni, "rangefinder").asIni();
}

inline std::string readText(const std::string& path)
{
	std::ifstream in(path);
	std::stringstream s;
	s << in.rdbuf();
	return s.str();
}

/** What `f` throws ("" if nothing). */
inline std::string errorOf(const std::function<void()>& f)
{
	try
	{
		f();
	}
	catch (const std::exception& e)
	{
		return e.what();
	}
	return "";
}

}  // namespace omnirange::test
