#include "omnirange/config/IniSectionWriter.h"

#include <omnirange/config/Output.h>
#include "omnirange/config/OptionsTable.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace omnirange
{
namespace
{
/** The line with its value replaced, its indentation kept. (MRPT's reader
 * has no comments after a value: `;` and `#` start comment lines only.) */
std::string withValue(const std::string& line, const std::string& key, const std::string& value)
{
	return line.substr(0, line.find_first_not_of(" \t")) + key + " = " + value;
}
}  // namespace

void requireSectionName(const std::string& section)
{
	const bool plain = !section.empty() && section.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
																	 "0123456789_-.") == std::string::npos;
	if (!plain)
		throw std::invalid_argument("section name '" + section + "': only letters, digits, '_', '-' and '.' make a [section] "
									"every reader takes back");
}

namespace
{
/** The ini `path` with the keys in, as read now; its state (fileStateOf()) when read. */
std::pair<std::string, std::string> withSection(const std::string& path, const std::string& section,
												 const std::vector<std::pair<std::string, std::string>>& values,
												 const std::map<std::string, std::string>& comments)
{
	const std::string state = fileStateOf(path);
	std::vector<std::string> lines;
	if (std::filesystem::exists(path))
	{
		// Keys go into a file every program will read strictly: one that
		// would be refused already is refused before anything is added.
		requireWellFormedIni(path);
		std::ifstream in(path);
		if (!in) throw std::runtime_error("cannot read ini file '" + path + "'");
		for (std::string l; std::getline(in, l);) lines.push_back(l);
	}
	// A file written with CRLF line ends (Windows editors) keeps them, every line alike.
	const bool crlf = !lines.empty() && !lines.front().empty() && lines.front().back() == '\r';
	for (auto& l : lines)
		if (!l.empty() && l.back() == '\r') l.pop_back();
	// MRPT finds a section and a key in any mix of case ([RangeFinder] is
	// [rangefinder]): so does the writer, or it would add a second one that
	// every reader refuses.
	const auto same_section = [&](const std::string& name) { return sameKey(name, section); };
	std::vector<std::pair<std::string, std::string>> pending = values;  // not yet in the file
	const auto pendingOf = [&](const std::string& key) {
		return std::find_if(pending.begin(), pending.end(), [&](const auto& kv) { return sameKey(kv.first, key); });
	};
	std::string current;
	int headers = 0;
	std::ptrdiff_t insert_at = -1;  // after the section's last key (or its header)
	for (std::size_t i = 0; i < lines.size(); ++i)
	{
		const IniLine line = parseIniLine(lines[i]);
		if (line.kind == IniLine::Kind::Section)
		{
			current = line.name;
			if (same_section(current) && ++headers > 1)
				throw std::runtime_error(path + ":" + std::to_string(i + 1) + ": section [" + section + "] appears twice");
			if (same_section(current)) insert_at = static_cast<std::ptrdiff_t>(i);
			continue;
		}
		if (!same_section(current) || line.kind != IniLine::Kind::Key) continue;
		insert_at = static_cast<std::ptrdiff_t>(i);
		if (const auto it = pendingOf(line.name); it != pending.end())
		{
			lines[i] = withValue(lines[i], line.name, it->second);
			pending.erase(it);
		}
	}
	std::vector<std::string> added;
	for (const auto& [key, value] : values)
	{
		if (pendingOf(key) == pending.end()) continue;
		if (const auto c = comments.find(key); c != comments.end()) added.push_back("; " + c->second);
		added.push_back(key + " = " + value);
	}
	if (insert_at < 0)
	{
		if (!lines.empty() && !trimmed(lines.back()).empty()) lines.emplace_back();
		lines.push_back("[" + section + "]");
		insert_at = static_cast<std::ptrdiff_t>(lines.size()) - 1;
	}
	lines.insert(lines.begin() + insert_at + 1, added.begin(), added.end());
	std::ostringstream out;
	for (const auto& l : lines) out << l << (crlf ? "\r\n" : "\n");
	return {out.str(), state};
}
}  // namespace

void writeIniSection(const std::string& path, const std::string& section,
					 const std::vector<std::pair<std::string, std::string>>& values,
					 const std::map<std::string, std::string>& comments, const IniSave& save)
{
	requireSectionName(section);
	// Another run's keys (two calibrations saving into one ini) or a user's edit that went in
	// meanwhile are read again and kept; a file that keeps changing is left as it is.
	constexpr int kTries = 5;
	// The file the caller checked: one replaced meanwhile by a link (to a base ini, another input) is not written through.
	const auto leadsTo = [&path] {
		std::error_code ec;
		return std::filesystem::weakly_canonical(path, ec).string();
	};
	const std::string checked = leadsTo();
	for (int attempt = 1;; ++attempt)
	{
		const auto [text, state] = withSection(path, section, values, comments);
		if (leadsTo() != checked)
			throw std::runtime_error("'" + path + "' now leads to '" + leadsTo() + "', not to the file it was checked as: " +
									 "nothing was saved");
		try
		{
			OutputSet set(save.program, save.inputs);
			set.write({path, OutputKind::Ini}, text);
			set.requireUnchanged(path, state);
			if (save.stage_with) save.stage_with(set);
			return set.commit();
		}
		catch (const ChangedMeanwhile&)
		{
			if (attempt == kTries) throw;
		}
	}
}

}  // namespace omnirange
