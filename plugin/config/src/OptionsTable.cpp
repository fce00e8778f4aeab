#include "omnirange/config/OptionsTable.h"

#include <linux/magic.h>
#include <sys/vfs.h>

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

namespace omnirange
{
std::string joined(const std::vector<std::string>& items)
{
	std::string all;
	for (const auto& item : items) all += (all.empty() ? "" : ", ") + item;
	return all;
}

std::string trimmed(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r\n");
	if (b == std::string::npos) return "";
	return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

double parseDouble(const std::string& text)
{
	const std::string t = trimmed(text);
	char* end = nullptr;
	errno = 0;
	const double v = std::strtod(t.c_str(), &end);
	if (t.empty() || end != t.c_str() + t.size()) throw std::invalid_argument("not a number (no unit, '.' for decimals)");
	// strtod also reads hexadecimal ("0x10", "0x1p-4"): no log or ini of ours writes numbers so.
	if (t.find_first_of("xX") != std::string::npos) throw std::invalid_argument("not a decimal number (no hexadecimal)");
	// ERANGE also for a number too near 0 to hold (1e-320): that one is no infinity.
	if (errno == ERANGE && std::isfinite(v) && std::abs(v) < 1)
		throw std::invalid_argument("too near 0 to hold as a double (write 0, or a number above 1e-300)");
	if (!std::isfinite(v) || errno == ERANGE) throw std::invalid_argument("not a finite number");
	return v;
}

double parseWithin(const std::string& text, double limit)
{
	const double v = parseDouble(text);
	if (std::abs(v) > limit) throw std::invalid_argument("not within [-" + formatDouble(limit) + ", " + formatDouble(limit) + "]");
	return v;
}

double parseTime(const std::string& text)
{
	const std::string t = trimmed(text);
	const auto digit = [](char c) { return c >= '0' && c <= '9'; };
	const std::size_t dot = t.find('.');
	const bool decimal = !t.empty() && t != "." && std::all_of(t.begin(), t.end(), [&](char c) { return digit(c) || c == '.'; }) &&
						 (dot == std::string::npos || t.find('.', dot + 1) == std::string::npos);
	if (!decimal) throw std::invalid_argument("not a time in decimal seconds");
	const double v = parseDouble(t);
	if (!(v < kMaxTime)) throw std::invalid_argument("past MRPT's clock (" + formatDouble(kMaxTime) + " s)");
	return v;
}

void requireRegularFile(const std::string& path, const std::string& what)
{
	std::error_code ec;
	if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
		throw std::runtime_error("the " + what + " '" + path + "' is not a regular file");
	// Else its reader says "no file": a loop of links (or one past 40) is something else.
	if (ec && ec != std::errc::no_such_file_or_directory)
		throw std::runtime_error("cannot reach the " + what + " '" + path + "' (" + ec.message() + ")");
	if (isKernelFile(path)) throw std::runtime_error("the " + what + " '" + path + "' is a file of the kernel's, not of data");
}

bool isKernelFile(const std::string& path)
{
	// The kernel's files look regular, but some never end or block (/proc/kmsg).
	struct statfs fs{};
	return ::statfs(path.c_str(), &fs) == 0 && (fs.f_type == PROC_SUPER_MAGIC || fs.f_type == SYSFS_MAGIC);
}

void requireNamedOnce(const std::vector<std::string>& files, const std::string& what)
{
	for (std::size_t i = 0; i < files.size(); ++i)
		for (std::size_t j = i + 1; j < files.size(); ++j)
			if (std::error_code ec; files[i] == files[j] || std::filesystem::equivalent(files[i], files[j], ec))
				throw std::invalid_argument(what + " '" + files[j] + "' is given twice (also as '" + files[i] + "')");
}

namespace
{
/** std::getline that stops at `cap` bytes: a file of one endless line (a
 * binary file given as a log) is found before it fills the memory. */
bool readLineUpTo(std::istream& in, std::string& line, std::size_t cap)
{
	line.clear();
	for (int c; (c = in.get()) != EOF;)
	{
		if (c == '\n') return true;
		line.push_back(static_cast<char>(c));
		if (line.size() >= cap) return true;
	}
	return !line.empty();
}
}  // namespace

bool readCappedLine(std::istream& in, std::string& line, const std::string& path, int line_number,
					const std::string& what)
{
	if (!readLineUpTo(in, line, kMaxLineBytes)) return false;
	if (line.size() >= kMaxLineBytes)
		throw std::runtime_error(path + ":" + std::to_string(line_number) + ": a line of more than " +
								 std::to_string(kMaxLineBytes >> 20) + " MB: is this the " + what + "?");
	return true;
}

int forEachDataLine(const std::string& path, const std::string& what,
					const std::function<void(int, const std::string&)>& row)
{
	requireRegularFile(path, what);
	std::ifstream in(path);
	if (!in) throw std::runtime_error("cannot read the " + what + " '" + path + "'");
	int rows = 0;
	std::string line;
	for (int n = 1; readCappedLine(in, line, path, n, what); ++n)
	{
		const std::string t = trimmed(line);
		if (t.empty() || t[0] == '#') continue;
		try
		{
			row(n, t);
		}
		catch (const std::invalid_argument& e)
		{
			throw std::runtime_error(path + ":" + std::to_string(n) + ": " + e.what());
		}
		++rows;
	}
	return rows;
}

std::vector<double> parseDoubles(const std::string& text)
{
	std::vector<double> v;
	std::istringstream in(text);
	std::string word;
	while (in >> word) v.push_back(parseDouble(word));
	return v;
}

std::string formatDoubles(const std::vector<double>& v)
{
	std::string s;
	for (const double x : v) s += (s.empty() ? "" : " ") + formatDouble(x);
	return s;
}

int parseInt(const std::string& text)
{
	const std::string t = trimmed(text);
	char* end = nullptr;
	errno = 0;
	const long v = std::strtol(t.c_str(), &end, 10);
	if (t.empty() || end != t.c_str() + t.size()) throw std::invalid_argument("not a whole number");
	if (errno == ERANGE || v < INT_MIN || v > INT_MAX) throw std::invalid_argument("out of range");
	return static_cast<int>(v);
}

std::uint32_t parseUint32(const std::string& text)
{
	const std::string t = trimmed(text);
	char* end = nullptr;
	errno = 0;
	const long long v = std::strtoll(t.c_str(), &end, 10);
	if (t.empty() || end != t.c_str() + t.size()) throw std::invalid_argument("not a whole number");
	if (errno == ERANGE || v < 0 || v > static_cast<long long>(UINT32_MAX)) throw std::invalid_argument("out of range");
	return static_cast<std::uint32_t>(v);
}

bool parseBool(const std::string& text)
{
	std::string t = trimmed(text);
	std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
	if (t == "true" || t == "yes" || t == "1") return true;
	if (t == "false" || t == "no" || t == "0") return false;
	throw std::invalid_argument("not true or false");
}

std::string formatDouble(double v)
{
	std::ostringstream o;
	o.precision(10);
	o << v;
	return o.str();
}

IniLine parseIniLine(const std::string& line)
{
	const std::string t = trimmed(line);
	if (t.empty() || t[0] == ';' || t[0] == '#') return {};
	if (t[0] == '[')
	{
		// "[name]", then at most a comment: MRPT reads no other line as a section.
		const auto close = t.find(']');
		const std::string after = close == std::string::npos ? "" : trimmed(t.substr(close + 1));
		if (close == std::string::npos || !(after.empty() || after[0] == ';' || after[0] == '#'))
			return {IniLine::Kind::Malformed, t};
		return {IniLine::Kind::Section, trimmed(t.substr(1, close - 1))};
	}
	const auto eq = t.find('=');
	if (eq == std::string::npos || eq == 0 || t.find('\0') != std::string::npos) return {IniLine::Kind::Malformed, t};
	return {IniLine::Kind::Key, trimmed(t.substr(0, eq))};
}

namespace
{
/** `text` with every byte that is not printable ASCII shown as '?': a binary
 * file given as an ini must not put raw bytes (or a NUL) in the message. */
std::string printable(std::string text)
{
	for (char& c : text)
		if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
	return text;
}

/** Calls `visit(section, key, line)` for every key line of the ini file, and
 * `visit(section, "", line)` for every section header. */
void forEachIniLine(const std::string& path,
					const std::function<void(const std::string&, const std::string&, int)>& visit)
{
	requireRegularFile(path, "ini file");
	std::error_code ec;
	if (const auto size = std::filesystem::file_size(path, ec); !ec && size > kMaxIniBytes)
		throw std::runtime_error("ini file '" + path + "' is larger than " + std::to_string(kMaxIniBytes >> 20) +
								 " MB: is it the ini meant?");
	std::ifstream f(path);
	if (!f) throw std::runtime_error("cannot open ini file '" + path + "'");
	std::string section;
	int n = 0;
	for (std::string line; std::getline(f, line);)
	{
		// Windows editors may save one; MRPT would read it as part of the first key or section.
		if (++n == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
			throw std::runtime_error(path + ":1: the file begins with a UTF-8 byte-order mark: save it without one "
											"(as plain UTF-8 or ASCII)");
		const IniLine l = parseIniLine(line);
		if (l.kind == IniLine::Kind::Section && l.name.empty())
			throw std::runtime_error(path + ":" + std::to_string(n) + ": a section with no name ('[]')");
		if (l.kind == IniLine::Kind::Section) section = l.name, visit(section, "", n);
		// Above the first section only `base` is read; MRPT would skip any other key there.
		else if (l.kind == IniLine::Kind::Key && section.empty() && l.name != "base")
			throw std::runtime_error(path + ":" + std::to_string(n) + ": key '" + printable(l.name) +
									 "' is above every [section]: no program reads it there");
		else if (l.kind == IniLine::Kind::Key) visit(section, l.name, n);
		else if (l.kind == IniLine::Kind::Malformed)
			throw std::runtime_error(path + ":" + std::to_string(n) + ": '" + printable(l.name.substr(0, 40)) +
									 "' is not 'key = value', a [section] or a comment (is it an ini file?)");
	}
}
}  // namespace

std::string Range::text() const
{
	const bool low = std::isfinite(lo), high = std::isfinite(hi);
	if (low && high)
		return std::string("within ") + (lo_open ? "(" : "[") + formatDouble(lo) + ", " + formatDouble(hi) +
			   (hi_open ? ")" : "]");
	if (low) return (lo_open ? "> " : ">= ") + formatDouble(lo);
	if (high) return (hi_open ? "< " : "<= ") + formatDouble(hi);
	return "finite";
}

std::string FieldInfo::rangeMessage() const
{
	const bool plain = unit.empty() || unit == "-" || unit == "bool";
	return "must be " + (range ? range->text() : std::string("valid")) + (plain ? "" : " " + unit);
}

std::string lowercase(std::string s)
{
	for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
	return s;
}

bool sameKey(const std::string& a, const std::string& b) { return lowercase(a) == lowercase(b); }

int requireWellFormedIni(const std::string& path)
{
	std::map<std::string, int> seen;  // "section/key", lower case (as MRPT matches them) -> line
	forEachIniLine(path, [&](const std::string& section, const std::string& key, int n) {
		if (key.empty()) return;
		const auto [it, fresh] = seen.emplace(lowercase(section + "/" + key), n);
		if (!fresh)
			throw std::runtime_error(path + ":" + std::to_string(n) + ": key '" + key + "' repeats in [" + section +
									 "] (first at line " + std::to_string(it->second) + "; case does not tell keys apart)");
	});
	return static_cast<int>(seen.size());
}

void requireNoRepeatedKeys(const std::string& path)
{
	if (requireWellFormedIni(path) == 0) throw std::runtime_error("ini file '" + path + "' holds no key: is it the ini meant?");
}

void requireOnlySections(const std::string& path, const std::vector<std::string>& known)
{
	forEachIniLine(path, [&](const std::string& section, const std::string& key, int n) {
		if (!key.empty() || std::find(known.begin(), known.end(), section) != known.end()) return;
		std::string all;
		for (const auto& k : known) all += (all.empty() ? "[" : ", [") + k + "]";
		throw std::runtime_error(path + ":" + std::to_string(n) + ": unknown section [" + section + "] (this file has " +
								 all + ")");
	});
}

std::vector<std::string> checkSectionKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
										  const std::vector<std::string>& known,
										  const std::vector<std::pair<std::string, std::string>>& renamed)
{
	if (!cfg.sectionExists(section)) throw std::invalid_argument("section [" + section + "] not found");
	std::vector<std::string> present;
	cfg.getAllKeys(section, present);
	// MRPT finds a key in any mix of case: so is it known in any (Threshold is threshold).
	const auto same = sameKey;
	for (const auto& k : present)
	{
		for (const auto& [old_key, instead] : renamed)
			if (same(k, old_key))
				throw KeyError("[" + section + "] key '" + k + "' is no longer read: " + instead, section, k);
		if (std::none_of(known.begin(), known.end(), [&](const std::string& key) { return same(k, key); }))
			throw KeyError("unknown key '" + k + "' in section [" + section + "]", section, k);
	}
	return present;
}

std::string readRawValue(const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key)
{
	return cfg.read_string(section, key, "", true);
}

}  // namespace omnirange
