#pragma once
// An ini file of ours over a base: a line `base = FILE` before the first
// section names another ini (relative to this file's folder) whose keys this
// one starts from; each key this file sets replaces the base's. A base may
// have a base of its own. Experiment inis use it to hold only what differs
// from ini/experiment-base.ini, so a default is written once.

#include <omnirange/config/OptionsTable.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace omnirange
{
struct LayeredIni
{
	/** The files read, the deepest base first and `path` last. */
	std::vector<std::string> files;
	/** Every section and key of all of them, later files winning. */
	std::shared_ptr<const mrpt::config::CConfigFileMemory> merged;
	/** "section/key" -> the file whose value `merged` holds: a relative path
	 * in a value is relative to the folder of the file that wrote it. */
	std::map<std::string, std::string> origin;

	/** The file that set `key` of `section` ("" if none did). */
	std::string originOf(const std::string& section, const std::string& key) const
	{
		const auto it = origin.find(section + "/" + key);
		return it == origin.end() ? std::string() : it->second;
	}
};

/** The folder an ini's relative paths (`base =`, an experiment's files)
 * are read from: the folder the file really is in, through links, since
 * that is where it was written beside them. */
std::filesystem::path iniFolderOf(const std::string& ini);

/** "FILE: why" for an error in the ini `path` read with its bases: FILE is
 * the base that set the key a KeyError names (or the key a message
 * "[section] key ..." begins with), else `path`. */
std::string namingItsFile(const LayeredIni& ini, const std::string& path, const std::exception& e);

/** The `base = FILE` of the ini `path`, resolved against its folder; "" if it has none. */
std::string iniBaseOf(const std::string& path);
/** Every base below the ini `path`, nearest first (at most 16 deep); none
 * if it has none or a base cannot be read (reading it says why). */
std::vector<std::string> iniBasesOf(const std::string& path);

/** Reads `path` and its bases. Each file must be a regular file with no key
 * repeated in a section; a missing base or a cycle of bases is an error.
 * Throws std::runtime_error naming the file. */
LayeredIni readLayeredIni(const std::string& path);

/** Reads [section] of the ini `path` (with its bases) into `s` through
 * `table`: an absent section or key keeps its value. Throws
 * std::runtime_error "FILE: why" on an unknown key or a bad value. */
template <class S>
void loadIniSection(const std::string& path, const std::string& section, const OptionsTable<S>& table, S& s)
{
	const LayeredIni ini = readLayeredIni(path);
	if (!ini.merged->sectionExists(section)) return;
	try
	{
		table.load(s, *ini.merged, section);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(namingItsFile(ini, path, e));
	}
}

}  // namespace omnirange
