#pragma once
// Writing one section of an ini file a person keeps: the tuner saves its
// [rangefinder] keys into the user's own ini, whose comments, blank lines,
// key order and other sections must survive.

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace omnirange
{
class OutputSet;

/** What goes in with an ini's keys: the program and the inputs the
 * guarantee is checked again for (Output.h), and files staged beside it. */
struct IniSave
{
	std::string program;
	std::vector<std::string> inputs;
	std::function<void(OutputSet&)> stage_with;
};

/** Sets `values` (key, value) in `section` of the ini file `path`. A key
 * already in the section keeps its line and indentation with the new value; keys not there go after the
 * section's last key, each after the line "; COMMENT" when `comments` has
 * one for it (OptionsTable::comments()); a missing section is appended; a
 * missing file is created. Every other line stays as it was. Written atomically (the old
 * file stays whole if anything fails). Throws std::runtime_error naming the
 * file if the section appears twice or the file cannot be read or written,
 * and requireSectionName()'s error before anything is read. `save`: files
 * staged beside it (what a calibration writes with these keys) go in with
 * the ini as one set: all or none. */
void writeIniSection(const std::string& path, const std::string& section,
					 const std::vector<std::pair<std::string, std::string>>& values,
					 const std::map<std::string, std::string>& comments = {}, const IniSave& save = {});

/** Throws std::invalid_argument unless `section` is a name an ini line can
 * hold and every reader takes back: letters, digits, '_', '-' and '.' (not
 * empty; no ']', blank or line end, which would write a line nothing reads). */
void requireSectionName(const std::string& section);

}  // namespace omnirange
