#include "omnirange/io/OutputRule.h"

#include "omnirange/config/AtomicWrite.h"
#include "omnirange/config/LayeredIni.h"
#include "omnirange/config/OptionsTable.h"
#include "omnirange/io/RawlogWriter.h"
#include "omnirange/config/Temporaries.h"

#include <signal.h>
#include <zlib.h>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <climits>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

namespace fs = std::filesystem;

namespace omnirange
{
std::string outputPath(const std::string& path)
{
	if (path.empty()) return path;
	// Only trailing slashes and '.' go: "a/link/.." is where the link leads, so
	// '..' is left for the system to resolve, as it will when the file is opened.
	std::string p = path;
	for (bool changed = true; changed;)
	{
		changed = false;
		while (p.size() > 1 && p.back() == '/') p.pop_back(), changed = true;
		if (p.size() > 2 && p.compare(p.size() - 2, 2, "/.") == 0) p.resize(p.size() - 2), changed = true;
	}
	return p;
}

std::string fileLedTo(const std::string& path)
{
	std::error_code ec;
	return fs::weakly_canonical(path, ec).string();
}

void requireStillLeadsTo(const std::string& path, const std::string& was, const std::string& since)
{
	if (const std::string now = fileLedTo(path); now != was)
		throw std::runtime_error("'" + path + "' now leads to '" + now + "', not to '" + was + "' as when " + since +
								 ": nothing was saved (run again)");
}

std::vector<std::string> markerLines(const std::string& dir)
{
	// Only a file of ours: a FIFO there would block, a link to /dev/zero never end.
	constexpr std::uintmax_t kLargestMarker = 64u << 20;
	const fs::path marker = fs::path(dir) / kOutputMarker;
	std::error_code ec;
	if (!fs::is_regular_file(fs::symlink_status(marker, ec)) || fs::file_size(marker, ec) > kLargestMarker) return {};
	std::ifstream f(marker);
	std::vector<std::string> lines;
	for (std::string l; std::getline(f, l);) lines.push_back(l);
	return lines;
}

namespace
{
/** A marker's line while its run writes files it has not listed (fillListed()). */
constexpr const char* kFilling = "filling";

std::string firstBytes(const std::string& path, std::size_t n)
{
	std::ifstream f(path, std::ios::binary);
	std::string b(n, '\0');
	f.read(b.data(), static_cast<std::streamsize>(n));
	b.resize(static_cast<std::size_t>(f.gcount()));
	return b;
}

bool isText(const std::string& bytes) { return bytes.find('\0') == std::string::npos; }

/** The first `n` bytes of the gzip file `path`, uncompressed ("" if it is
 * not one): an MRPT object's class name is in them. */
std::string unzippedHead(const std::string& path, unsigned n)
{
	gzFile f = ::gzopen(path.c_str(), "rb");
	if (!f) return "";
	std::string b(n, '\0');
	const int got = ::gzread(f, b.data(), n);
	::gzclose_r(f);
	b.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
	return b;
}

bool isIni(const std::string& path)
{
	const std::string head = firstBytes(path, 4096);
	if (!isText(head)) return false;
	std::ifstream f(path);
	for (std::string line; std::getline(f, line);)
	{
		const std::string t = trimmed(line);
		if (t.empty()) continue;
		return t[0] == ';' || t[0] == '#' || t[0] == '[' || parseIniLine(t).kind == IniLine::Kind::Key;
	}
	return true;  // blank: nothing to lose
}


const char* kindName(OutputKind kind)
{
	switch (kind)
	{
		case OutputKind::Rawlog: return "a rawlog";
		case OutputKind::GridMap: return "a grid map";
		case OutputKind::Histogram: return "a colour model";
		case OutputKind::Ini: return "an ini file";
		case OutputKind::Text: return "a text file";
		case OutputKind::Image: return "an image";
		case OutputKind::Folder: return "a folder";
	}
	return "";
}

/** `path` as written, made absolute, without its "." parts, each ".."
 * leaving the folder before it (through a link, as the system goes: to the
 * parent of the folder the link names). */
fs::path asWritten(const std::string& path)
{
	fs::path out;
	std::error_code ec;
	for (const auto& part : fs::absolute(path))
	{
		if (part == "." || part.empty()) continue;
		// "dir/.." leaves dir ("o_lc/../x" is not in "o_lc"): for a link, to the parent of what it names, as the system goes.
		if (part == ".." && out.has_relative_path())
			out = (fs::is_symlink(out, ec) ? fs::weakly_canonical(out, ec) : out).parent_path();
		else out /= part;
	}
	return out;
}

/** Where `path` is written: links and '..' resolved as the system goes; past PATH_MAX, where no
 * path resolves, as written. */
fs::path whereWritten(const std::string& path)
{
	std::error_code ec;
	const fs::path real = fs::weakly_canonical(fs::absolute(path, ec), ec);
	return ec ? asWritten(path) : real;
}

/** `inner` is `outer` or lies somewhere below it. */
bool within(const fs::path& inner, const fs::path& outer)
{
	auto i = inner.begin(), o = outer.begin();
	for (; o != outer.end(); ++i, ++o)
		if (i == inner.end() || *i != *o) return false;
	return true;
}

/** The inputs and what each brings with it: an ini's bases (`base = FILE`,
 * followed down the chain) and a rawlog's images folder (NAME_Images), which
 * are read as surely as the file named. */
std::vector<std::string> withWhatInputsBring(const std::vector<std::string>& inputs)
{
	std::vector<std::string> all;
	std::error_code ec;
	for (const auto& in : inputs)
	{
		if (in.empty()) continue;
		all.push_back(in);
		if (!fs::is_regular_file(in, ec) || isKernelFile(in)) continue;  // read by its reader, which refuses it
		if (isOfKind(in, OutputKind::Rawlog) || fs::path(in).extension() == ".rawlog")
			all.push_back(imagesDirToRead(in));
		else if (isIni(in))
			for (const auto& base : iniBasesOf(in)) all.push_back(base);
	}
	return all;
}

/** `inner` is `outer` or lies below it, by the device and inode of each
 * folder up from it: the same folder reached by another path (a bind mount)
 * is found too. Only what exists is compared. */
bool withinByIdentity(const fs::path& inner, const fs::path& outer)
{
	std::error_code ec;
	if (!fs::is_directory(outer, ec)) return false;
	for (fs::path p = inner;; p = p.parent_path())
	{
		if (fs::exists(p, ec) && fs::equivalent(p, outer, ec)) return true;
		if (p == p.parent_path() || p.empty()) return false;
	}
}

/** The same file or folder: by path through links, or by device and inode (a hard link). */
bool same(const fs::path& a, const fs::path& b)
{
	std::error_code ec;
	return a == b || (fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec));
}

}  // namespace

void requireApartFromInputs(const std::string& output, OutputKind kind, const std::vector<std::string>& given)
{
	const std::vector<std::string> inputs = withWhatInputsBring(given);
	std::error_code ec;
	// A linked folder is replaced as a link (nothing it points to is lost); a
	// linked file is written through, so the file it names is the output.
	const fs::path abs = asWritten(output);
	const bool link_itself = kind == OutputKind::Folder && fs::is_symlink(abs, ec);
	// Resolved as the system goes; as written where it cannot be (a path past PATH_MAX gives none, inside every folder).
	const auto resolved = [](const fs::path& p) {
		std::error_code failed;
		const fs::path r = fs::weakly_canonical(p, failed);
		return failed || r.empty() ? p : r;
	};
	const fs::path out = link_itself ? resolved(abs.parent_path()) / abs.filename() : resolved(abs);
	for (const auto& in : inputs)
	{
		if (in.empty()) continue;
		// A link that leads back to itself names no place: every path would seem inside it.
		(void)fs::canonical(fs::absolute(outputPath(in)), ec);
		if (ec == std::errc::too_many_symbolic_link_levels)
			throw std::runtime_error("the input '" + in + "' is a link that leads back to itself, or one of more than 40 in " +
									 "a row (the system follows no more)");
		const fs::path input_as_written = asWritten(outputPath(in));
		const fs::path input = resolved(fs::absolute(outputPath(in)));
		// A link replaced as a link is its own path, not the folder it names.
		if ((link_itself ? out == input : same(out, input)) || input_as_written == abs)
			throw std::runtime_error("the output '" + output + "' is the input '" + in + "': refusing to overwrite it");
		// Also as written: a folder that reaches an input through a link holds it too.
		const bool holds_as_written = within(input_as_written, abs);
		// By identity too, but not through a link replaced as a link (nothing it names is touched).
		if (within(input, out) || holds_as_written || (!link_itself && withinByIdentity(input, out)))
			throw std::runtime_error("the output '" + output + "' holds the input '" + in + "': refusing to replace it");
		if (within(out, input) || withinByIdentity(link_itself ? out.parent_path() : out, input))
			throw std::runtime_error("the output '" + output + "' is inside the input '" + in + "': write it elsewhere");
	}
}

/** Every file and link under `dir` but its marker (and a killed run's
 * temporary of it: ..omnirange-output.tmp-PID), relative to it. */
std::vector<std::string> filesIn(const std::string& dir)
{
	std::vector<std::string> files;
	std::error_code walking, ec;
	for (auto it = fs::recursive_directory_iterator(dir, walking); !walking && it != fs::recursive_directory_iterator();
		 it.increment(walking))
		// Files, links, and empty folders (a user's new folder is as much theirs as a file).
		if (it->is_symlink(ec) || !it->is_directory(ec) || fs::is_empty(it->path(), ec))
			// Lexically: fs::relative would follow a link to where it points ("../userdata").
			if (std::string rel = it->path().lexically_relative(dir).string();
				rel != kOutputMarker && rel.rfind(std::string(".") + kOutputMarker + ".tmp-", 0) != 0)
				files.push_back(rel);
	return files;
}

/** The system lets this user look where `output` is: a folder on the way
 * without search permission would make every later answer about it wrong. */
void requireReachable(const std::string& output)
{
	std::error_code ec;
	(void)fs::symlink_status(output, ec);
	if (ec == std::errc::filename_too_long && output.size() >= PATH_MAX)
		throw std::runtime_error("cannot reach the output '..." + output.substr(output.size() - 60) + "': its path is " +
								 std::to_string(output.size()) + " characters, and the system takes at most " +
								 std::to_string(PATH_MAX - 1) + " (write it from a folder with a shorter path)");
	if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
		throw std::runtime_error("cannot reach the output '" + output + "' (" + ec.message() + ")");
}

/** A name the file system takes, with room for the run's own suffixes
 * (".staging-PID", "_Images.tmp-PID"); the message shows the name's end,
 * which tells a name the program derives (PREFIX_histogram.png) from another. */
void requireNameFits(const std::string& output)
{
	// Markers and journals hold one name a line, fields split by tabs: such a name would read back as others.
	if (std::any_of(output.begin(), output.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
	{
		std::string shown = output;
		std::replace_if(shown.begin(), shown.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }, '?');
		throw std::runtime_error("the output '" + shown + "' has a control character (a line break, a tab) in its path, " +
								 "shown as '?': name it without");
	}
	constexpr std::size_t kLongestName = NAME_MAX - 32;
	const std::string name = fs::path(output).filename().string();
	if (isTemporaryName(name))
		throw std::runtime_error("the output's name '" + name + "' has the form runs give their temporaries " +
								 "(NAME.staging-PID, .NAME.tmp-PID, .NAME.old-PID, .NAME.commit-PID): a later run would " +
								 "take it for a killed run's leftover; give another name");
	if (name.size() <= kLongestName) return;
	throw std::runtime_error("the output's name '" + name.substr(0, 12) + "..." + name.substr(name.size() - 20) + "' is " +
							 std::to_string(name.size()) + " characters: at most " + std::to_string(kLongestName) +
							 " leave room for the names of its temporaries");
}

std::set<std::string> listedIn(const std::string& dir, bool& has_list)
{
	std::set<std::string> listed;
	has_list = false;
	for (const auto& line : markerLines(dir))
		if (line.rfind("file ", 0) == 0) listed.insert(line.substr(5)), has_list = true;
	return listed;
}

void requireNotAnothersPart(const std::string& output, const std::string& program)
{
	// Where it is written: through links (to a report's file, or to a folder inside one) and '..' as the system
	// goes; past PATH_MAX no absolute path opens, so the folders around it are read as it was given, from here.
	fs::path out = whereWritten(outputPath(output));
	if (out.string().size() >= PATH_MAX) out = fs::path(outputPath(output)).lexically_normal();
	for (fs::path dir = out.parent_path(); dir.has_relative_path(); dir = dir.parent_path())
	{
		const auto lines = markerLines(dir.string());
		if (lines.empty()) continue;
		const std::string writer = trimmed(lines.front());
		// A folder this run is filling (an experiment's stages): one of its own temporaries, not a folder whose
		// marker merely has this PID (every run in a container of its own is PID 1).
		if (writer == program || temporaries::holds(dir.string())) continue;
		// What that folder lists as its own, or a folder holding some of it: replaced, the rest would no longer match.
		bool has_list = false;
		const std::string rel = out.lexically_relative(dir).string();
		for (const auto& own : listedIn(dir.string(), has_list))
			if (own == rel || own.rfind(rel + "/", 0) == 0)
				throw std::runtime_error("'" + output + "' is part of '" + dir.string() + "', which " + writer +
										 " wrote, not " + program + " (give another output)");
	}
}

void requireOutputAllowed(const std::string& output_as_given, OutputKind kind, const std::string& program,
						  const std::vector<std::string>& inputs, bool force, const std::string& begins_with)
{
	const std::string output = outputPath(output_as_given);
	if (output.empty()) return;
	if (kind != OutputKind::Folder && output_as_given.back() == '/')
		throw std::runtime_error("'" + output_as_given + "' ends with '/', which names a folder: this output is a file");
	requireNameFits(output);
	requireReachable(output);
	// "a/missing/..": the system cannot pass through a folder that is not there, though the text reads as "a".
	fs::path walked;
	for (const auto& part : fs::path(output_as_given))
	{
		std::error_code ec;
		if (part == ".." && !walked.empty() && !fs::is_directory(walked, ec))
			throw std::runtime_error("'" + output_as_given + "' passes through '" + walked.string() +
									 "', which is not a folder");
		walked /= part;
	}
	requireApartFromInputs(output, kind, inputs);
	if (!force && !program.empty()) requireNotAnothersPart(output, program);
	// A file output's temporaries that killed runs left (a folder's are its
	// writer's to recover: StagedFolder, RawlogWriter).
	if (kind != OutputKind::Folder) recoverLeftoversOf(output, kind, "", begins_with);
	const fs::path p(output);
	std::error_code ec;
	// A link is the user's: replaced (not what it names) only when they say so.
	if (kind == OutputKind::Folder && fs::is_symlink(p, ec))
	{
		if (force) return;
		throw std::runtime_error("the output folder '" + output + "' is a symbolic link (remove it, or give another output)");
	}
	const auto status = fs::status(p, ec);  // through symlinks
	// A link that names nothing would be replaced by a file: the link is the user's.
	if (!fs::exists(status) && fs::is_symlink(p, ec))
		throw std::runtime_error("the output '" + output + "' is a symbolic link to '" + fs::read_symlink(p, ec).string() +
								 "', which does not exist (remove the link, or give another output)");
	if (!fs::exists(status))
	{
		// Moved aside by a killed run of another program, it stands for that program's output still.
		if (const std::string old = kind == OutputKind::Folder && !force ? halfReplaced(output) : "";
			!old.empty() && !isOutputFolderOf(old, program))
			throw std::runtime_error("'" + output + "' is missing: a run that was replacing it was killed, leaving the " +
									 "old one in '" + old + "', which " + program + " did not write (run the program " +
									 "that wrote it again, or give another output)");
		return;
	}
	const std::string hint = force ? "" : " (remove it, or give another output)";
	if (kind == OutputKind::Folder)
	{
		if (!fs::is_directory(status))
			throw std::runtime_error("the output folder '" + output + "' is a file" + (force ? "" : " (give another output)"));
		if (force || fs::is_empty(p, ec)) return;
		if (!isOutputFolderOf(output, program))
		{
			// Another program's output is not the user's to remove: say whose it is, and advise no removal.
			const auto lines = markerLines(output);
			if (!lines.empty() && !trimmed(lines.front()).empty())
				throw std::runtime_error("'" + output + "' is what " + trimmed(lines.front()) + " wrote, not " + program +
										 " (give another output)");
			const bool odd = fs::exists(fs::symlink_status(p / kOutputMarker, ec)) &&
							 !fs::is_regular_file(fs::symlink_status(p / kOutputMarker, ec));
			throw std::runtime_error("'" + output + "' is a folder " + program + " did not write (" +
									 (odd ? std::string("its ") + kOutputMarker + " is a link or not a file, no marker of ours"
										  : std::string("no ") + kOutputMarker + " naming it") +
									 ")" + hint);
		}
		// The folder is the program's, but what a user put in it since is not.
		if (const std::string added = firstUnlistedIn(output); !added.empty())
			throw std::runtime_error("'" + (p / added).string() + "' is not something " + program +
									 " wrote into its output '" + output + "' (move it out, or give another output)");
		// Replacing it notes in its marker and renames it (moveAside()): found now, not after the run.
		if (::access((p / kOutputMarker).c_str(), W_OK) != 0)
			throw std::runtime_error("'" + output + "' cannot be replaced: its marker '" + kOutputMarker +
									 "' cannot be written (" + std::strerror(errno) + ")");
		if (const std::string why = whyCannotReplace(output); !why.empty())
			throw std::runtime_error("'" + output + "' cannot be replaced (" + why + ")");
		return;
	}
	if (!fs::is_regular_file(status))
		throw std::runtime_error("the output '" + output + "' exists and is not a file");
	replacedFileOf(output);  // a read-only file is refused before any work, --force or not
	if (!force && isOfKind(output, kind) && firstBytes(output, begins_with.size()) != begins_with)
		throw std::runtime_error("'" + output + "' exists and is not what " + program + " writes there (it begins '" +
								 begins_with.substr(0, begins_with.find('\n')) + "')" + hint);
	if (force || isOfKind(output, kind)) return;
	throw std::runtime_error("'" + output + "' exists and is not " + kindName(kind) + hint);
}

void requireDistinctOutputs(const std::vector<std::string>& paths)
{
	for (std::size_t i = 0; i < paths.size(); ++i)
		for (std::size_t j = i + 1; j < paths.size(); ++j)
		{
			const std::string a = outputPath(paths[i]), b = outputPath(paths[j]);
			if (a.empty() || b.empty()) continue;
			const fs::path pa = whereWritten(a), pb = whereWritten(b);
			if (same(pa, pb) || within(pa, pb) || within(pb, pa))
				throw std::runtime_error("the outputs '" + paths[i] + "' and '" + paths[j] +
										 "' are in the same place: one would replace the other");
		}
}

void requireOutputsAllowed(const std::vector<Output>& outputs, const std::string& program,
						   const std::vector<std::string>& inputs, bool force)
{
	std::vector<std::string> paths;
	for (const auto& o : outputs)
		if (!o.path.empty()) paths.push_back(o.path), requireNameFits(outputPath(o.path)), requireReachable(outputPath(o.path));
	requireDistinctOutputs(paths);
	for (const auto& o : outputs) requireOutputAllowed(o.path, o.kind, program, inputs, force, o.begins_with);
}

namespace
{
/** Renames `from` to TARGET.replaced-PID, or TARGET.replaced-PID-N where that
 * is taken (a container's runs are all PID 1): where a folder an output
 * replaced is kept, never onto another such. Sets `kept` to the name. */
void moveToKept(const std::string& from, const std::string& target, std::string& kept, std::error_code& ec)
{
	const std::string first = target + ".replaced-" + std::to_string(::getpid());
	for (int n = 1; n <= 1000; ++n)
	{
		kept = n == 1 ? first : first + "-" + std::to_string(n);
		renameNotReplacing(from, kept, ec);
		if (ec.value() != EEXIST) return;
	}
}
}  // namespace

MovedAside moveAside(const std::string& target, bool force)
{
	const std::string old = target + ".old-" + std::to_string(::getpid()), aside = "aside " + std::to_string(::getpid());
	std::error_code ec;
	// The proof that TARGET.old-PID is this run's and not a user's backup of that name (added only to a
	// marker still there: a folder put in its place since has none to add to).
	const bool noted = !fs::is_symlink(target, ec) && fs::exists(fs::path(target) / kOutputMarker, ec);
	if (!noted && !force && fs::is_directory(fs::symlink_status(target, ec)) && !fs::is_empty(target, ec))
		throw std::runtime_error("cannot move '" + target + "' aside to replace it (it holds what this program did " +
								 "not write: made or filled while the run went?); it is as it was");
	// Not this program's, replaced with --force: kept at once under the name it keeps (a run killed now leaves it
	// there, in no run's way and taken by none for a leftover).
	if (!noted && force && fs::is_directory(fs::symlink_status(target, ec)) && !fs::is_empty(target, ec))
	{
		std::string kept;
		moveToKept(target, target, kept, ec);
		if (!ec) return {kept, false, true, true};
		throw std::runtime_error("cannot move '" + target + "' aside to replace it (" + ec.message() + "); it is as it was");
	}
	try
	{
		if (noted) noteInMarker(target, aside, false);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error("cannot move '" + target + "' aside to replace it (" + e.what() + "); it is as it was");
	}
	renameNotReplacing(target, old, ec);
	if (!ec) return {old, noted, force};
	// Not moved: a copy made of it later must not read as moved aside by this run.
	if (noted) unnoteInMarker(target, aside);
	throw std::runtime_error("cannot move '" + target + "' aside to replace it (" +
							 (ec.value() == EEXIST ? "'" + old + "' is in the way, and is not this program's to remove: " +
														 "move it away"
												   : ec.message()) +
							 "); it is as it was");
}

void replaceFolder(const std::string& target, const std::string& fresh, bool force)
{
	const FolderLock lock(target);
	MovedAside old;
	std::error_code ec;
	const bool had_old = fs::exists(fs::symlink_status(target, ec));
	if (had_old) old = moveAside(target, force);
	try
	{
		fs::rename(fresh, target);
	}
	catch (const std::exception& e)
	{
		if (had_old) renameNotReplacing(old.path, target, ec);
		// Not put back (a folder made at its name meanwhile): said where it is.
		throw std::runtime_error("cannot move '" + fresh + "' to '" + target + "' (" + e.what() + "); " +
								 (had_old && ec ? "the old output is in '" + old.path + "' (" + ec.message() + ")"
												: "'" + target + "' is as it was"));
	}
	if (had_old) removeReplaced(old);
}

namespace
{
/** The run `pid` is over: its leftovers are nobody's run's. */
bool deadRun(const std::string& pid) { return temporaries::runGone(pid); }

/** `p` is a folder whose marker has `line`. */
bool markerSays(const fs::path& p, const std::string& line)
{
	std::error_code ec;
	if (fs::is_symlink(p, ec) || !fs::is_directory(p, ec)) return false;
	const auto lines = markerLines(p.string());
	return std::find(lines.begin(), lines.end(), line) != lines.end();
}

/** `p` is a folder whose marker names the run that made it or moved it aside
 * (a marker cut short, by a run killed writing it, names none). */
bool markerNamesARun(const fs::path& p)
{
	for (const auto& l : markerLines(p.string()))
		if (l.rfind("run ", 0) == 0 || l.rfind("aside ", 0) == 0) return true;
	return false;
}

/** `p` is a folder run `pid` made (markOutputFolder()). */
bool madeBy(const fs::path& p, const std::string& pid) { return markerSays(p, "run " + pid); }

/** Removes `p`, its marker last (what cannot be removed whole stays a
 * folder of ours); "" or the system's reason it could not. */
std::string removedMarkerLast(const fs::path& p)
{
	std::error_code ec, failed;
	std::vector<fs::path> inside;
	if (fs::is_directory(fs::symlink_status(p, ec)))
		for (const auto& e : fs::directory_iterator(p, ec))
			if (e.path().filename() != kOutputMarker) inside.push_back(e.path());
	for (const auto& q : inside)
		if (fs::remove_all(q, ec); ec && !failed) failed = ec;
	fs::remove_all(p, ec);
	if (!fs::exists(fs::symlink_status(p, ec))) return "";
	return failed ? failed.message() : "a file in it could not be removed";
}

/** `p` is a folder whose marker says run `pid` moved it aside (moveAside()). */
bool movedAsideBy(const fs::path& p, const std::string& pid) { return markerSays(p, "aside " + pid); }

/** The first thing under `dir` that the run `pid` did not write, relative to
 * `dir` ("" if none). A folder its run was killed filling (fillListed()) is
 * all its own; one with a list of its files (listOutputFile()) is compared
 * with it; one without (a run killed before it listed them) holds only what
 * runs write before they list: a hidden temporary of run `pid`
 * (temporaryOf()), a folder made by run `pid`, a plain folder holding only
 * these. */
std::string firstNotMadeBy(const fs::path& dir, const std::string& pid)
{
	if (markerSays(dir, kFilling)) return "";  // killed in fillListed(): what it had not listed yet is its own too
	bool has_list = false;
	listedIn(dir.string(), has_list);
	if (has_list) return firstUnlistedIn(dir.string());
	std::error_code ec;
	for (const auto& e : fs::directory_iterator(dir, ec))
	{
		const std::string name = e.path().filename().string();
		const std::string tmp = ".tmp-" + pid;
		if (name == kOutputMarker) continue;
		if (fs::is_directory(fs::symlink_status(e.path(), ec)))
		{
			if (const std::string inner = firstNotMadeBy(e.path(), pid); !inner.empty()) return name + "/" + inner;
		}
		else if (!(name.front() == '.' && name.size() > tmp.size() &&
				   name.compare(name.size() - tmp.size(), tmp.size(), tmp) == 0))
			return name;
	}
	return "";
}

/** TARGET.old-PID that run PID, now gone, moved aside (halfReplaced()). */
std::string halfReplacedItself(const std::string& target)
{
	const fs::path t(target);
	const fs::path dir = t.parent_path().empty() ? fs::path(".") : t.parent_path();
	const std::string prefix = t.filename().string() + ".old-";
	std::error_code ec;
	for (const auto& e : fs::directory_iterator(dir, ec))
		if (const std::string name = e.path().filename().string(); name.rfind(prefix, 0) == 0)
			if (const std::string pid = name.substr(prefix.size()); deadRun(pid) && movedAsideBy(e.path(), pid))
				return e.path().string();
	return "";
}
}  // namespace

void removeReplaced(const MovedAside& aside)
{
	const std::string& old = aside.path;
	// Noted as ours: what says otherwise now was put there by someone while the run committed (or given with --force).
	std::string theirs;
	if (aside.noted && !movedAsideBy(old, std::to_string(::getpid())))
		theirs = "its marker no longer says this run moved it aside (a folder put in its place meanwhile?)";
	else if (const std::string added = aside.noted ? firstUnlistedIn(old) : ""; !added.empty())
		theirs = "it holds '" + added + "', which the output did not list";
	else if (std::error_code ec; !aside.noted && fs::is_directory(fs::symlink_status(old, ec)))
	{
		// No marker: a folder --force replaced, or one filled after the run found it empty. Kept all the same.
		if (const auto files = filesIn(old); !files.empty())
			theirs = "it holds '" + files.front() + "', and " +
					 (aside.forced ? "is no output of this program (replaced with --force)" : "was empty when the run looked");
	}
	const std::string why = theirs.empty() ? removedMarkerLast(old) : "";
	if (theirs.empty() && why.empty()) return;
	// Renamed, so that no reader takes it for an output half replaced (halfReplaced()).
	std::string kept = old;
	std::error_code ec;
	if (const auto at = old.rfind(".old-"); !aside.kept && at != std::string::npos)
		moveToKept(old, old.substr(0, at), kept, ec);
	temporaries::warn(theirs.empty() ? "could not remove the replaced '" + (ec ? old : kept) + "' (" + why +
										   "): the new output is whole; remove that folder yourself"
									 : "kept '" + (ec ? old : kept) + "', what the output replaced: " + theirs +
										   "; the new output is whole");
}

std::string halfReplaced(const std::string& target)
{
	std::error_code ec;
	// A folder it is in that is missing: the run may have been killed between moving it aside and putting the new in.
	for (fs::path up = fs::absolute(target, ec).lexically_normal().parent_path(); up.has_relative_path(); up = up.parent_path())
		if (!fs::exists(fs::symlink_status(up, ec)))
			if (const std::string old = halfReplacedItself(up.string()); !old.empty()) return old;
	return halfReplacedItself(target);
}


void recoverLeftoversOf(const std::string& target, OutputKind kind, const std::string& program,
						const std::string& begins_with)
{
	const fs::path t(target);
	const fs::path dir = t.parent_path().empty() ? fs::path(".") : t.parent_path();
	std::error_code ec;
	if (!fs::is_directory(dir, ec)) return;
	const std::string name = t.filename().string();
	if (kind != OutputKind::Folder) recoverSetOf(target);  // a set of files a killed run was putting in place
	// Inside the output: its marker's temporary, from a run killed rewriting it (the marker's name is ours).
	if (kind == OutputKind::Folder && fs::is_directory(fs::symlink_status(t, ec)))
		for (const auto& e : fs::directory_iterator(t, ec))
		{
			const std::string other = e.path().filename().string(), prefix = std::string(".") + kOutputMarker + ".tmp-";
			if (other.rfind(prefix, 0) != 0 || !fs::is_regular_file(fs::symlink_status(e.path(), ec))) continue;
			if (const std::string pid = other.substr(prefix.size()); pid == std::to_string(::getpid()) || deadRun(pid))
				fs::remove(e.path(), ec);
		}
	// Only what our runs leave: a folder holding the marker; a file of the
	// output's kind, or empty (killed before it wrote). A user's file that
	// merely has such a name is left alone.
	const auto marked = [&](const fs::path& p) {
		return program.empty() ? fs::exists(p / kOutputMarker, ec) : isOutputFolderOf(p.string(), program);
	};
	// A folder: what in it the run did not make (firstNotMadeBy()); a file: not of the output's kind.
	const auto notOurs = [&](const fs::path& p, const std::string& pid) -> std::string {
		if (fs::is_directory(fs::symlink_status(p, ec))) return marked(p) ? firstNotMadeBy(p, pid) : p.string();
		if (kind == OutputKind::Folder || !fs::is_regular_file(fs::symlink_status(p, ec))) return p.string();
		if (fs::file_size(p, ec) == 0) return "";
		// Begun as this output begins, or cut short within that: a user's notes are text too.
		const std::string head = firstBytes(p.string(), begins_with.size());
		return isOfKind(p.string(), kind) && begins_with.compare(0, head.size(), head) == 0 ? "" : p.string();
	};
	for (const auto& e : fs::directory_iterator(dir, ec))
	{
		const std::string other = e.path().filename().string();
		// A temporary of one of its temporaries (written whole itself: a journal, a staged ini): "..NAME.commit-PID.tmp-PID".
		for (const auto& prefix : {".." + name + ".tmp-", ".." + name + ".commit-"})
		{
			if (other.rfind(prefix, 0) != 0) continue;
			const std::string rest = other.substr(prefix.size());
			const auto at = rest.find(".tmp-");
			const std::string pid = rest.substr(0, at);
			if (at != std::string::npos && rest.substr(at + 5) == pid &&
				(pid == std::to_string(::getpid()) || deadRun(pid)) && fs::is_regular_file(fs::symlink_status(e.path(), ec)))
				fs::remove(e.path(), ec);
		}
		// What a run names its leftovers (temporaryOf(), StagedFolder, moveAside()).
		for (const auto& prefix : {name + ".staging-", "." + name + ".tmp-", name + ".old-", "." + name + ".old-"})
		{
			if (other.rfind(prefix, 0) != 0) continue;
			const std::string pid = other.substr(prefix.size());
			// This run's PID: an earlier run's that had it (a container's PID 1), as this one has made nothing here yet.
			if (pid != std::to_string(::getpid()) && !deadRun(pid)) continue;  // not a PID, or a run still going
			// A folder is that run's only if its marker says so: "NAME.old-2024" or
			// "NAME.staging-2024" may be a user's copy of a report, marker and all.
			const bool old = prefix == name + ".old-";
			// A file's temporaries are hidden (temporaryOf(), commitAll()'s old copies): "f.hist.staging-2023" is a user's copy.
			const bool hidden = prefix == "." + name + ".tmp-" || prefix == "." + name + ".old-";
			// Killed removing it after its marker went, or making it before its marker named the run: nothing in it
			// to be anyone's.
			if (fs::is_directory(fs::symlink_status(e.path(), ec)) && filesIn(e.path().string()).empty() &&
				!markerNamesARun(e.path()))
			{
				fs::remove_all(e.path(), ec);
				continue;
			}
			if (!fs::is_directory(fs::symlink_status(e.path(), ec)) && !hidden) continue;
			if (fs::is_directory(fs::symlink_status(e.path(), ec)) &&
				!(marked(e.path()) && (old ? movedAsideBy(e.path(), pid) : madeBy(e.path(), pid))))
				continue;
			// An old copy put back where its output is missing is moved, not removed: its being ours is enough.
			if (old && !fs::exists(fs::symlink_status(t, ec)))
				fs::rename(e.path(), t, ec);
			// The output's name taken by what is not this program's (a folder made there meanwhile): the old copy is the
			// only output left.
			else if (old && !marked(t))
				temporaries::warn("kept '" + e.path().string() + "', the output a killed or failed run moved aside: '" +
								  t.string() + "' is not this program's output (rename one of them)");
			else if (const std::string added = notOurs(e.path(), pid); added.empty())
			{
				if (const std::string why = removedMarkerLast(e.path()); !why.empty())
					temporaries::warn("could not remove '" + e.path().string() + "', a killed run's leftover (" + why + ")");
			}
			else if (fs::is_directory(e.path(), ec))
			{
				// Out of the names runs take (in a container, the next run's own): kept where no run will need it.
				std::string kept;
				moveToKept(e.path().string(), t.string(), kept, ec);
				temporaries::warn("kept '" + (ec ? e.path().string() : kept) + "', a killed run's leftover: it holds '" +
								  added + "', which that run did not write (remove the folder once nothing in it is yours)");
			}
		}
	}
}

namespace
{
/** `path` as a folder output: "." or ".." (`-o .` in a folder made for it) by
 * the folder's own name, so that its staging folder and the old one go beside it. */
std::string folderOutputOf(const std::string& path)
{
	const std::string p = outputPath(path);
	const std::string name = fs::path(p).filename().string();
	std::error_code ec;
	const fs::path real = fs::canonical(p, ec);
	return (name == "." || name == "..") && !ec ? real.string() : p;
}
}  // namespace

StagedFolder::StagedFolder(const std::string& target, const std::string& program,
						   const std::vector<std::string>& inputs, bool force)
	: target_(folderOutputOf(target)),
	  staging_(target_ + ".staging-" + std::to_string(::getpid())),
	  program_(program),
	  inputs_(inputs),
	  force_(force)
{
	recoverLeftoversOf(target_, OutputKind::Folder, program);
	requireOutputAllowed(target_, OutputKind::Folder, program, inputs, force);
	requireNothingAt(staging_, "staging folder");
	temporaries::add(staging_);
	try
	{
		errno = 0;
		fs::create_directories(staging_);
		markOutputFolder(staging_, program);
	}
	catch (const std::exception& e)
	{
		temporaries::forget(staging_);
		std::error_code ec;
		fs::remove_all(staging_, ec);
		// The system's reason (read-only, no permission, no space), not std::filesystem's text.
		const auto* fe = dynamic_cast<const fs::filesystem_error*>(&e);
		throw std::runtime_error("cannot write the output '" + target_ + "' (" + (fe ? fe->code().message() : e.what()) +
								 ")");
	}
}

void StagedFolder::fill(const std::function<void()>& write) const
{
	try
	{
		fillListed(staging_, write);  // killed while it writes, the folder is all this run's: the next run removes it
	}
	catch (const std::exception& e)
	{
		if (std::string(e.what()).find(staging_) == std::string::npos) throw;
		throw std::runtime_error(namingTheOutput(e.what(), staging_, target_));
	}
}

StagedFolder::~StagedFolder()
{
	if (done_) return;
	temporaries::forget(staging_);
	std::error_code ec;
	fs::remove_all(staging_, ec);
}

void StagedFolder::commit()
{
	try
	{
		requireOutputAllowed(target_, OutputKind::Folder, program_, inputs_, force_);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(std::string("the output was made but not put in place, as what is there changed while "
											 "the run went: ") + e.what());
	}
	listOutputFolder(staging_);
	replaceFolder(target_, staging_, force_);  // if it fails, the old folder is back and the staging goes with this object
	temporaries::forget(staging_);
	done_ = true;
}

void StagedFolder::keep()
{
	temporaries::forget(staging_);
	done_ = true;
}

void noteInMarker(const std::string& dir, const std::string& line, bool create)
{
	// One note a line: a file named with a line break (an input's image) would read back as two.
	if (line.find_first_of("\n\r") != std::string::npos)
		throw std::runtime_error("cannot note '" + line.substr(0, line.find_first_of("\n\r")) + "...' in the marker of '" +
								 dir + "': a name with a line break");
	std::error_code ec;
	// Written through, a link would carry the line into a file that is not this folder's.
	const fs::path marker = fs::path(dir) / kOutputMarker;
	if (fs::is_symlink(marker, ec) || (fs::exists(fs::symlink_status(marker, ec)) && !fs::is_regular_file(marker, ec)))
		throw std::runtime_error("the marker '" + marker.string() + "' is a link or not a file, not a marker of ours");
	// Opened as checked: no link followed, and (without `create`) no marker made in a folder put there since.
	const int fd = ::open(marker.c_str(), O_WRONLY | O_APPEND | O_NOFOLLOW | O_CLOEXEC | (create ? O_CREAT : 0), 0644);
	if (fd < 0 && errno == ENOENT && !create)
		throw std::runtime_error("its marker is gone: was it replaced meanwhile?");
	if (fd < 0) throw std::runtime_error(cannotWrite(marker.string()));
	const std::string text = line + "\n";
	errno = 0;
	const bool whole = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
	const int write_errno = errno;
	if (::close(fd) != 0 || !whole)
	{
		errno = write_errno ? write_errno : errno;
		throw std::runtime_error(cannotWrite(marker.string(), "is the disk full?"));
	}
}

bool unnoteInMarker(const std::string& dir, const std::string& line)
{
	const std::string marker = (fs::path(dir) / kOutputMarker).string();
	std::string kept;
	bool had = false;
	for (const auto& l : markerLines(dir))
		if (l != line) kept += l + "\n";
		else had = true;
	if (had) writeFileAtomically(marker, kept);
	return had;
}

std::string markerValue(const std::string& dir, const std::string& key)
{
	for (const auto& l : markerLines(dir))
		if (l.rfind(key + " ", 0) == 0) return l.substr(key.size() + 1);
	return "";
}

void requireRawlogOfImages(const std::string& rawlog, const std::string& images)
{
	// Through a link too (a user's, or a scan's of before 2026-11-27): those are another rawlog's.
	std::error_code ec;
	const std::string content = markerValue(images, "content");
	if (content.empty()) return;
	// A rawlog that does not read whole is refused by its reading, with the reason.
	if (const auto now = contentCrcOf(rawlog); now && std::to_string(*now) != content)
		throw std::runtime_error("'" + rawlog + "' is not the rawlog '" + images + "' were written with (its content " +
								 "differs): a rawlog put there by hand is not read with another's images (" +
								 (fs::is_symlink(images, ec)
									  ? "they are reached through a link: make it again from its input, or give it a copy of its own"
									  : "if they are its images, remove '" + (fs::path(images) / kOutputMarker).string() + "'") +
								 ")");
}

void listOutputFile(const std::string& dir, const std::string& name) { noteInMarker(dir, "file " + name); }

void fillListed(const std::string& dir, const std::function<void()>& write)
{
	noteInMarker(dir, kFilling);
	const auto listed = [&] {
		listOutputFolder(dir);
		unnoteInMarker(dir, kFilling);
	};
	try
	{
		write();
	}
	catch (...)
	{
		try
		{
			listed();
		}
		catch (const std::exception&)  // not listed: still all the run's, which the next run removes
		{
		}
		throw;
	}
	listed();
}

void listOutputFolder(const std::string& dir)
{
	bool has_list = false;
	const std::set<std::string> listed = listedIn(dir, has_list);
	for (const auto& e : filesIn(dir))
		if (!listed.count(e)) listOutputFile(dir, e);
}

std::string firstUnlistedIn(const std::string& dir)
{
	// A marker that lists nothing (cut short, or written before markers listed files) vouches for no file.
	bool has_list = false;
	const std::set<std::string> listed = listedIn(dir, has_list);
	// An empty folder its files were listed in is the run's, emptied (a run killed removing it).
	const auto heldListed = [&](const std::string& rel) {
		const auto next = listed.lower_bound(rel + "/");
		return next != listed.end() && next->rfind(rel + "/", 0) == 0;
	};
	for (const auto& rel : filesIn(dir))
		if (!listed.count(rel) && !heldListed(rel)) return rel;
	return "";
}

void markOutputFolder(const std::string& dir, const std::string& program)
{
	errno = 0;
	std::ofstream f(fs::path(dir) / kOutputMarker);
	f << program << "\nrun " << ::getpid() << "\n";  // the run: a leftover of it is told from a copy
	f.close();  // a full disk fails here, not at the buffered writes: an empty marker would name no one
	if (!f) throw std::runtime_error(cannotWrite((fs::path(dir) / kOutputMarker).string(), "is the disk full?"));
}

bool isOutputFolderOf(const std::string& dir, const std::string& program)
{
	const auto lines = markerLines(dir);
	return !lines.empty() && trimmed(lines.front()) == program;
}

bool isOfKind(const std::string& path, OutputKind kind)
{
	const std::string head = firstBytes(path, 8);
	switch (kind)
	{
		case OutputKind::Rawlog:  // by its first object's class, not by being gzip (a user's .tar.gz is gzip too)
		{
			const std::string first = unzippedHead(path, 64);
			for (const char* cls : {"CObservation", "CSensoryFrame", "CActionCollection", "CRawlog"})
				if (first.find(cls) != std::string::npos) return true;
			return false;
		}
		case OutputKind::GridMap: return unzippedHead(path, 64).find("COccupancyGridMap2D") != std::string::npos;
		case OutputKind::Histogram: return head == "OMNIHIST";
		case OutputKind::Ini: return isIni(path);
		case OutputKind::Text: return isText(firstBytes(path, 4096));
		case OutputKind::Image: return head.rfind("\x89PNG", 0) == 0 || head.rfind("\xff\xd8\xff", 0) == 0;
		case OutputKind::Folder: return false;
	}
	return false;
}

}  // namespace omnirange
