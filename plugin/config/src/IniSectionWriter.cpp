#include "omnirange/config/IniSectionWriter.h"

#include "omnirange/config/AtomicWrite.h"
#include "omnirange/config/OptionsTable.h"

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

void writeIniSection(const std::string& path, const std::string& section,
					 const std::vector<std::pair<std::string, std::string>>& values,
					 const std::map<std::string, std::string>& comments)
{
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
	std::map<std::string, std::string> pending(values.begin(), values.end());
	std::string current;
	int headers = 0;
	std::ptrdiff_t insert_at = -1;  // after the section's last key (or its header)
	for (std::size_t i = 0; i < lines.size(); ++i)
	{
		const IniLine line = parseIniLine(lines[i]);
		if (line.kind == IniLine::Kind::Section)
		{
			current = line.name;
			if (current == section && ++headers > 1)
				throw std::runtime_error(path + ":" + std::to_string(i + 1) + ": section [" + section + "] appears twice");
			if (current == section) insert_at = static_cast<std::ptrdiff_t>(i);
			continue;
		}
		if (current != section || line.kind != IniLine::Kind::Key) continue;
		insert_at = static_cast<std::ptrdiff_t>(i);
		if (const auto it = pending.find(line.name); it != pending.end())
		{
			lines[i] = withValue(lines[i], line.name, it->second);
			pending.erase(it);
		}
	}
	std::vector<std::string> added;
	for (const auto& [key, value] : values)
	{
		if (!pending.count(key)) continue;
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
	writeFileAtomically(path, out.str());
}

}  // namespace omnirange
