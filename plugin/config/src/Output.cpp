#include "omnirange/config/Output.h"

#include "omnirange/config/LayeredIni.h"
#include "omnirange/config/OptionsTable.h"
#include "omnirange/config/Activity.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace omnirange
{
namespace
{
constexpr const char* kStagingPrefix = ".omnirange-";  // mkdtemp's ".omnirange-XXXXXX"
// In a staging folder, held by flock while its run lives; at commit, "INODE REPLACES NAME" per entry that
// goes in: its inode, and fileStateOf() what it replaces as the commit checked it ("-": nothing).
constexpr const char* kCommitList = ".omnirange-commit";

std::string firstBytes(const std::string& path, std::size_t n)
{
	std::ifstream f(path, std::ios::binary);
	std::string b(n, '\0');
	f.read(b.data(), static_cast<std::streamsize>(n));
	b.resize(static_cast<std::size_t>(f.gcount()));
	return b;
}

/** The first `n` bytes of the gzip file `path`, uncompressed ("" if it is not one). */
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
	if (firstBytes(path, 4096).find('\0') != std::string::npos) return false;
	std::ifstream f(path);
	for (std::string line; std::getline(f, line);)
		if (const std::string t = trimmed(line); !t.empty())
			return t[0] == ';' || t[0] == '#' || t[0] == '[' || parseIniLine(t).kind == IniLine::Kind::Key;
	return true;  // blank: nothing to lose
}

const char* kindName(OutputKind kind)
{
	constexpr const char* names[] = {"a rawlog", "a grid map", "a colour model", "an ini file", "a text file", "an image", "a folder"};
	return names[static_cast<int>(kind)];
}

/** `path` absolute and resolved as the system goes; where it cannot be (past PATH_MAX), as written. */
fs::path whereWritten(const std::string& path)
{
	std::error_code ec;
	const fs::path real = fs::weakly_canonical(fs::absolute(path, ec), ec);
	return ec || real.empty() ? fs::absolute(path, ec).lexically_normal() : real;
}

/** `inner` is `outer` or lies below it: by path, or by the identity of each folder up from it (a bind mount). */
bool within(const fs::path& inner, const fs::path& outer)
{
	const auto [o, i] = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
	if (o == outer.end()) return true;
	std::error_code ec;
	if (!fs::is_directory(outer, ec)) return false;
	for (fs::path p = inner; !p.empty() && p != p.parent_path(); p = p.parent_path())
		if (fs::exists(p, ec) && fs::equivalent(p, outer, ec)) return true;
	return false;
}

/** The same place: by path through links, or by device and inode (a hard link). */
bool same(const fs::path& a, const fs::path& b)
{
	std::error_code ec;
	return a == b || (fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec));
}

/** The inputs and what each brings: a rawlog's images folder, an ini's bases. */
std::vector<std::string> withWhatInputsBring(const std::vector<std::string>& inputs)
{
	std::vector<std::string> all;
	std::error_code ec;
	for (const auto& in : inputs)
	{
		if (in.empty()) continue;
		all.push_back(outputPath(in));
		if (!fs::is_regular_file(in, ec) || isKernelFile(in)) continue;  // its reader refuses it
		if (isOfKind(in, OutputKind::Rawlog) || fs::path(in).extension() == ".rawlog")
			all.push_back(imagesDirToRead(in));
		else if (isIni(in))
			for (const auto& base : iniBasesOf(in)) all.push_back(base);
	}
	return all;
}

/** Where `output` is written (through links, as every output is) is no input, holds none and lies in none. */
void requireApartFromInputs(const std::string& output, const std::vector<std::string>& inputs)
{
	std::error_code ec;
	const fs::path out = whereWritten(output);
	for (const auto& in : withWhatInputsBring(inputs))
	{
		(void)fs::canonical(fs::absolute(in), ec);
		if (ec == std::errc::too_many_symbolic_link_levels)
			throw std::runtime_error("the input '" + in + "' is a link that leads back to itself, or one of more than 40 in a row");
		const fs::path input = whereWritten(in);
		if (same(out, input))
			throw std::runtime_error("the output '" + output + "' is the input '" + in + "': refusing to overwrite it");
		if (within(input, out))
			throw std::runtime_error("the output '" + output + "' holds the input '" + in + "': refusing to replace it");
		if (within(out, input))
			throw std::runtime_error("the output '" + output + "' is inside the input '" + in + "': write it elsewhere");
	}
}

/** The lines of the marker in the folder `dir` (none when it has no plain file of that name of a marker's size). */
std::vector<std::string> markerLines(const std::string& dir)
{
	// Only a plain file of a marker's size: a FIFO there would block, a link to /dev/zero never end.
	const fs::path marker = fs::path(dir) / kOutputMarker;
	std::error_code ec;
	if (!fs::is_regular_file(fs::symlink_status(marker, ec)) || fs::file_size(marker, ec) > (64u << 20)) return {};
	std::ifstream f(marker);
	std::vector<std::string> lines;
	for (std::string l; std::getline(f, l);) lines.push_back(l);
	return lines;
}

/** Every file, link and empty folder under `dir` but its marker, relative to it. */
std::vector<std::string> filesIn(const std::string& dir)
{
	std::vector<std::string> files;
	std::error_code walking, ec;
	for (auto it = fs::recursive_directory_iterator(dir, walking); !walking && it != fs::recursive_directory_iterator();
		 it.increment(walking))
		if (it->is_symlink(ec) || !it->is_directory(ec) || fs::is_empty(it->path(), ec))
			if (std::string rel = it->path().lexically_relative(dir).string(); rel != kOutputMarker) files.push_back(rel);
	return files;
}

/** A file in the marked folder `dir` its marker does not list, or "". */
std::string firstUnlistedIn(const std::string& dir)
{
	std::set<std::string> listed;
	for (const auto& line : markerLines(dir))
		if (line.rfind("file ", 0) == 0) listed.insert(line.substr(5));
	for (const auto& rel : filesIn(dir))
		if (!listed.count(rel)) return rel;
	return "";
}

std::string writerOf(const std::string& dir)
{
	const auto lines = markerLines(dir);
	return lines.empty() ? "" : trimmed(lines.front());
}

/** A name the file system takes, one line, and not of the staging folders' form. */
void requireNameFits(const std::string& output)
{
	if (std::any_of(output.begin(), output.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
		throw std::runtime_error("the output '" + output + "' has a control character (a line break, a tab) in its path: "
								 "name it without");
	const std::string name = fs::path(output).filename().string();
	if (name.rfind(kStagingPrefix, 0) == 0)
		throw std::runtime_error("the output's name '" + name + "' begins as the runs' staging folders do (" + kStagingPrefix +
								 "): give another name");
	std::error_code ec;  // a name or a path too long for the system is refused here
	(void)fs::symlink_status(output, ec);
	if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
		throw std::runtime_error("cannot reach the output '" + output + "' (" + ec.message() + ")");
}

/** `output` is not a file a folder around it, marked by another program, lists as its own. */
void requireNotAnothersPart(const std::string& output, const std::string& program)
{
	const fs::path out = whereWritten(output);
	for (fs::path dir = out.parent_path(); dir.has_relative_path(); dir = dir.parent_path())
		if (const std::string writer = writerOf(dir.string()); !writer.empty() && writer != program)
		{
			const std::string rel = out.lexically_relative(dir).string();
			for (const auto& line : markerLines(dir.string()))
				if (line == "file " + rel || line.rfind("file " + rel + "/", 0) == 0)
					throw std::runtime_error("'" + output + "' is part of '" + dir.string() + "', which " + writer +
											 " wrote, not " + program + " (give another output)");
		}
}

/** Why the folder `parent` cannot hold `output` ("" when it can): said before any work, not at the commit. */
std::string folderMissing(const fs::path& parent, const std::string& output)
{
	std::error_code ec;
	if (parent.empty() || fs::is_directory(parent, ec)) return "";
	return "the folder '" + parent.string() + "' of the output '" + output + "' " +
		   (fs::exists(parent, ec) ? "is not a folder" : "does not exist (make it first)");
}

/** After access(W_OK) failed: the file's mode, or the file system mounted read-only. */
std::string readOnlyWhy() { return errno == EROFS ? "is on a read-only file system" : "is read-only"; }

void requireFolderAllowed(const std::string& output, const std::string& program, bool force)
{
	std::error_code ec;
	if (!fs::exists(output, ec) || force) return;
	if (!fs::is_directory(output, ec))
		throw std::runtime_error("the output folder '" + output + "' is a file (give another output)");
	// Moved to the staging folder by the exchange, a folder must be writable (its ".." changes).
	errno = 0;
	if (::access(output.c_str(), W_OK) != 0)
		throw std::runtime_error("the output folder '" + output + "' " + readOnlyWhy() + ": refusing to replace it");
	if (fs::is_empty(output, ec)) return;
	if (const std::string writer = writerOf(output); writer != program)
		throw std::runtime_error("'" + output + "' is " + (writer.empty() ? "a folder " + program + " did not write" : "what " + writer + " wrote, not " + program) +
								 " (remove it, or give another output)");
	if (const std::string added = firstUnlistedIn(output); !added.empty())
		throw std::runtime_error("'" + (fs::path(output) / added).string() + "' is not something " + program +
								 " wrote into its output '" + output + "' (move it out, or give another output)");
}

void requireFileAllowed(const Output& o, const std::string& output, const std::string& program, bool force)
{
	std::error_code ec;
	const auto status = fs::status(output, ec);
	if (!fs::exists(status)) return;
	if (!fs::is_regular_file(status)) throw std::runtime_error("the output '" + output + "' exists and is not a file");
	errno = 0;
	if (::access(output.c_str(), W_OK) != 0 || (status.permissions() & fs::perms::owner_write) == fs::perms::none)
		throw std::runtime_error("'" + output + "' " + readOnlyWhy() + ": refusing to replace it");
	// In a sticky folder (as /tmp) only the file's or the folder's owner may rename over it.
	struct stat folder{}, file{};
	const std::string parent = fs::path(output).parent_path().empty() ? "." : fs::path(output).parent_path().string();
	if (::stat(parent.c_str(), &folder) == 0 && ::stat(output.c_str(), &file) == 0 && (folder.st_mode & S_ISVTX) &&
		::geteuid() != 0 && file.st_uid != ::geteuid() && folder.st_uid != ::geteuid())
		throw std::runtime_error("'" + output + "' cannot be replaced: it belongs to another user, in a folder where only "
								 "its owner may rename it");
	if (force) return;
	const std::string hint = " (remove it, or give another output)";
	if (!isOfKind(output, o.kind)) throw std::runtime_error("'" + output + "' exists and is not " + kindName(o.kind) + hint);
	if (firstBytes(output, o.begins_with.size()) != o.begins_with)
		throw std::runtime_error("'" + output + "' exists and is not what " + program + " writes there (it begins '" +
								 o.begins_with.substr(0, o.begins_with.find('\n')) + "')" + hint);
}

void requireAllowed(const Output& o, const std::string& program, const std::vector<std::string>& inputs, bool force)
{
	const std::string given = outputPath(o.path);
	if (given.empty()) return;
	if (o.kind != OutputKind::Folder && o.path.back() == '/')
		throw std::runtime_error("'" + o.path + "' ends with '/', which names a folder: this output is a file");
	requireNameFits(given);
	requireApartFromInputs(given, inputs);
	if (!force && !program.empty()) requireNotAnothersPart(given, program);
	// A link, to a file or a folder, is written through: what it leads to is replaced, the link stays.
	std::error_code ec;
	if (fs::is_symlink(given, ec) && !fs::exists(given, ec))
		throw std::runtime_error("the output '" + given + "' is a symbolic link to '" + fs::read_symlink(given, ec).string() +
								 "', which does not exist (remove the link, or give another output)");
	const std::string output = writtenThrough(given);
	if (const std::string why = folderMissing(fs::path(output).parent_path(), given); !why.empty()) throw std::runtime_error(why);
	if (o.kind == OutputKind::Folder) return requireFolderAllowed(output, program, force);
	requireFileAllowed(o, output, program, force);
}

/** flock on a folder while it lives: runs making, recovering or committing staging folders there take turns. */
struct FolderLock
{
	explicit FolderLock(const std::string& dir) : fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC))
	{
		if (fd >= 0) ::flock(fd, LOCK_EX);
	}
	~FolderLock()
	{
		if (fd >= 0) ::close(fd);
	}
	FolderLock(const FolderLock&) = delete;
	FolderLock& operator=(const FolderLock&) = delete;
	int fd;
};

ino_t inodeOf(const std::string& path)
{
	struct stat st{};
	return ::lstat(path.c_str(), &st) == 0 ? st.st_ino : 0;
}

/** `staged` put at `target`: a folder exchanged with the one there (the old
 * one left where the new was), a file renamed over. */
void place(const std::string& staged, const std::string& target)
{
	std::error_code ec;
	const bool exchange = fs::is_directory(fs::symlink_status(staged, ec)) && fs::exists(fs::symlink_status(target, ec));
	if (::renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD, target.c_str(), exchange ? RENAME_EXCHANGE : 0) != 0)
		throw std::runtime_error("cannot put '" + target + "' in place (" + std::strerror(errno) + ")");
}

/** A killed run's commit finished: every entry its list names put in, once, and only over what the
 * commit checked (a file edited or put there since is the user's, and stays). */
void finishCommit(const std::string& parent, const std::string& staging)
{
	std::ifstream list(fs::path(staging) / kCommitList);
	for (std::string line; std::getline(list, line);)
	{
		std::istringstream in(line);
		ino_t ino = 0;
		std::string replaces, name;
		if (!(in >> ino >> replaces) || !std::getline(in.ignore(1), name)) continue;
		const std::string target = parent + "/" + name, staged = staging + "/" + name;
		if (inodeOf(target) != ino && inodeOf(staged) == ino && fileStateOf(target) == (replaces == "-" ? "" : replaces))
			place(staged, target);
	}
}

/** What killed runs left in `parent`: staging folders whose lock is free. */
void recoverLeftoversIn(const std::string& parent)
{
	std::error_code ec;
	for (const auto& e : fs::directory_iterator(parent, ec))
	{
		const std::string name = e.path().filename().string();
		if (name.rfind(kStagingPrefix, 0) != 0 || name.size() != std::strlen(kStagingPrefix) + 6 ||
			!e.is_directory(ec) || e.is_symlink(ec))
			continue;
		const int fd = ::open((e.path() / kCommitList).c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
		const bool live = fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) != 0;
		if (!live) finishCommit(parent, e.path().string()), fs::remove_all(e.path(), ec);
		if (fd >= 0) ::close(fd);
	}
}

/** What killed runs left beside each of `paths`, recovered (above). */
void finishKilledCommitsBeside(const std::vector<std::string>& paths)
{
	std::error_code ec;
	for (const auto& path : paths)
	{
		if (path.empty() || !fs::exists(path, ec)) continue;
		const fs::path parent = fs::path(fileLedTo(path)).parent_path();
		if (!fs::is_directory(parent, ec)) continue;
		const FolderLock beside(parent.string());
		recoverLeftoversIn(parent.string());
	}
}

/** The marker of the staged folder `dir`: `program`, then every file in it. */
void markFolder(const std::string& dir, const std::string& program)
{
	std::string text = program + "\n";
	for (const auto& rel : filesIn(dir)) text += "file " + rel + "\n";
	std::ofstream f(fs::path(dir) / kOutputMarker, std::ios::binary);
	f << text;
	f.close();
	if (!f) throw std::runtime_error(cannotWrite((fs::path(dir) / kOutputMarker).string(), "is the disk full?"));
}

void syncFile(const std::string& path, const std::string& what)
{
	const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
	const bool ok = fd >= 0 && ::fsync(fd) == 0;
	if (fd >= 0) ::close(fd);
	if (!ok) throw std::runtime_error("cannot write '" + what + "' to disk (" + std::strerror(errno) + ")");
}
}  // namespace

std::string outputPath(const std::string& path)
{
	// Only trailing slashes and '.' go: "a/link/.." is where the link leads, for the system to resolve.
	std::string p = path;
	while (p.size() > 1 && (p.back() == '/' || (p.size() > 2 && p.compare(p.size() - 2, 2, "/.") == 0)))
		p.resize(p.size() - (p.back() == '/' ? 1 : 2));
	return p;
}

bool isOfKind(const std::string& path, OutputKind kind)
{
	const std::string head = firstBytes(path, 8);
	switch (kind)
	{
		case OutputKind::Rawlog:  // by its first object's class, not by being gzip (a .tar.gz is gzip too)
		{
			const std::string first = unzippedHead(path, 64);
			for (const char* cls : {"CObservation", "CSensoryFrame", "CActionCollection", "CRawlog"})
				if (first.find(cls) != std::string::npos) return true;
			return false;
		}
		case OutputKind::GridMap: return unzippedHead(path, 64).find("COccupancyGridMap2D") != std::string::npos;
		case OutputKind::Histogram: return head == "OMNIHIST";
		case OutputKind::Ini: return isIni(path);
		case OutputKind::Text: return firstBytes(path, 4096).find('\0') == std::string::npos;
		case OutputKind::Image: return head.rfind("\x89PNG", 0) == 0 || head.rfind("\xff\xd8\xff", 0) == 0;
		case OutputKind::Folder: return false;
	}
	return false;
}

void requireOutputsAllowed(const std::vector<Output>& outputs, const std::string& program,
						   const std::vector<std::string>& inputs, bool force)
{
	finishKilledCommitsBeside(inputs);  // an input is read whole: a killed run's commit there is finished first
	for (std::size_t i = 0; i < outputs.size(); ++i)
		for (std::size_t j = i + 1; j < outputs.size() && !outputs[i].path.empty(); ++j)
		{
			if (outputs[j].path.empty()) continue;
			const fs::path a = whereWritten(outputPath(outputs[i].path)), b = whereWritten(outputPath(outputs[j].path));
			if (same(a, b) || within(a, b) || within(b, a))
				throw std::runtime_error("the outputs '" + outputs[i].path + "' and '" + outputs[j].path +
										 "' are in the same place: one would replace the other");
		}
	for (const auto& o : outputs) requireAllowed(o, program, inputs, force);
}

struct OutputSet::Staged
{
	Output output;
	std::string target, parent, staged;  ///< the file or folder replaced (links followed), its folder, where it is written
	std::optional<std::string> state;  ///< requireUnchanged()
};

struct OutputSet::Folder
{
	std::string parent, path;
	int list_fd;  ///< kCommitList's, locked while the run lives: no later run takes the folder for a leftover
};

OutputSet::OutputSet(std::string program, std::vector<std::string> inputs, bool force)
	: program_(std::move(program)), inputs_(std::move(inputs)), force_(force)
{
}

OutputSet::~OutputSet()
{
	for (auto& f : folders_)
	{
		std::error_code ec;
		if (!kept_ && (fs::remove_all(f.path, ec), ec) && done_)  // the new outputs are in: say it, do not fail
			activity::warn("could not remove the replaced outputs in '" + f.path + "' (" + ec.message() + ")");
		::close(f.list_fd);
	}
}

OutputSet::Folder& OutputSet::folderFor(const std::string& parent, const std::string& output)
{
	for (auto& f : folders_)
		if (f.parent == parent) return f;
	const FolderLock beside(parent);  // no other run's recovery meanwhile takes the new folder for a leftover
	recoverLeftoversIn(parent);
	std::string path = parent + "/" + kStagingPrefix + "XXXXXX";
	errno = 0;
	if (!::mkdtemp(path.data()))
	{
		const std::string why = folderMissing(parent, output);
		throw std::runtime_error(!why.empty() ? why : cannotWrite(output, "cannot make a folder beside it"));
	}
	const int fd = ::open((path + "/" + kCommitList).c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
	if (fd < 0 || ::flock(fd, LOCK_EX) != 0) throw std::runtime_error(cannotWrite(path + "/" + kCommitList));
	folders_.push_back({parent, path, fd});
	return folders_.back();
}

std::string OutputSet::stage(const Output& output)
{
	const std::string given = outputPath(output.path);
	// Written through a link: the file or folder it leads to is replaced, the link stays.
	const std::string target = writtenThrough(given);
	const fs::path p(target);
	const std::string parent = p.parent_path().empty() ? "." : p.parent_path().string();
	const std::string staged = folderFor(parent, output.path).path + "/" + p.filename().string();
	staged_.push_back({output, target, parent, staged, std::nullopt});
	return staged;
}

void OutputSet::write(const Output& output, const std::function<void(const std::string&)>& writer) { writer(stage(output)); }

void OutputSet::write(const Output& output, const std::string& bytes)
{
	write(output, [&](const std::string& tmp) {
		errno = 0;
		std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
		if (!f) throw std::runtime_error(cannotWrite(output.path));
		f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
		f.close();
		if (!f) throw std::runtime_error(cannotWrite(output.path, "is the disk full?"));
	});
}

void OutputSet::requireUnchanged(const std::string& path, const std::string& state)
{
	for (auto& s : staged_)
		if (s.output.path == path) s.state = state;
}

void OutputSet::ready(const Staged& s) const
{
	std::error_code ec;
	if (fs::is_directory(fs::symlink_status(s.staged, ec))) markFolder(s.staged, program_);
	else if (fs::is_regular_file(s.target, ec)) fs::permissions(s.staged, fs::status(s.target, ec).permissions(), ec);
	else if (fs::is_regular_file(s.staged, ec)) syncFile(s.staged, s.output.path);
	// --force: a folder not ours is kept under one name, never removed.
	if (force_ && fs::is_directory(fs::symlink_status(s.target, ec)) && writerOf(s.target) != program_ &&
		!fs::is_empty(s.target, ec) &&
		::renameat2(AT_FDCWD, s.target.c_str(), AT_FDCWD, (s.target + ".replaced").c_str(), RENAME_NOREPLACE) != 0)
		throw std::runtime_error("cannot keep '" + s.target + "' as '" + s.target + ".replaced' (" + std::strerror(errno) + ")");
}

void OutputSet::writeLists(const std::vector<const Staged*>& order) const
{
	for (const auto& f : folders_)
	{
		std::string list;
		for (const Staged* s : order)
			if (s->parent == f.parent)
			{
				const std::string replaces = s->state ? *s->state : fileStateOf(s->target);  // an update: as it was read
				list += std::to_string(inodeOf(s->staged)) + " " + (replaces.empty() ? "-" : replaces) + " " +
						fs::path(s->staged).filename().string() + "\n";
			}
		errno = 0;
		if (::pwrite(f.list_fd, list.data(), list.size(), 0) != static_cast<ssize_t>(list.size()) || ::fsync(f.list_fd) != 0)
			throw std::runtime_error(cannotWrite(f.path + "/" + kCommitList, "is the disk full?"));
	}
}

/** An update (requireUnchanged) put in by exchange, so that what it replaced
 * can be looked at after the move: changed since check() (an editor saved in
 * between), it is exchanged back and nothing is replaced. Created meanwhile
 * where there was nothing: refused the same way. */
void OutputSet::placeUpdate(const Staged& s) const
{
	const std::string changed = "'" + s.output.path + "' changed while the run went (another run or an editor wrote it): nothing was saved";
	const bool existed = !s.state->empty();
	if (::renameat2(AT_FDCWD, s.staged.c_str(), AT_FDCWD, s.target.c_str(), existed ? RENAME_EXCHANGE : RENAME_NOREPLACE) != 0)
	{
		if (errno == EEXIST || errno == ENOENT) throw ChangedMeanwhile(changed);
		throw std::runtime_error("cannot put '" + s.target + "' in place (" + std::strerror(errno) + ")");
	}
	if (existed && fileStateOf(s.staged) != *s.state)
	{
		// Back, and the refused update removed: a later run finishing this commit must not put it in.
		::renameat2(AT_FDCWD, s.staged.c_str(), AT_FDCWD, s.target.c_str(), RENAME_EXCHANGE);
		::unlink(s.staged.c_str());
		throw ChangedMeanwhile(changed);
	}
}

void OutputSet::commit()
{
	if (done_) return;
	std::error_code ec;
	// Updates first (one found changed at its move stops the commit before any other), then as staged: the
	// file that names the others (a rawlog) last. What was staged and never written has nothing to put in.
	std::vector<const Staged*> order;
	for (const bool updates : {true, false})
		for (const auto& s : staged_)
			if (s.state.has_value() == updates && fs::exists(fs::symlink_status(s.staged, ec))) order.push_back(&s);
	std::vector<std::string> parents;
	for (const auto& f : folders_) parents.push_back(f.parent);
	std::sort(parents.begin(), parents.end());  // two runs lock in one order: neither waits for the other
	std::vector<std::unique_ptr<FolderLock>> locks;  // two runs' commits here do not interleave
	for (const auto& p : parents) locks.push_back(std::make_unique<FolderLock>(p));
	for (const Staged* s : order)  // all checked before anything moves: a refusal replaces nothing
		if (!program_.empty()) requireAllowed({s->target, s->output.kind, s->output.begins_with}, program_, inputs_, force_);
	for (const Staged* s : order) ready(*s);
	writeLists(order);
	for (std::size_t i = 0; i < order.size(); ++i)
		try
		{
			if (order[i]->state) placeUpdate(*order[i]);
			else place(order[i]->staged, order[i]->target);
		}
		catch (const std::exception& e)
		{
			if (i == 0 && dynamic_cast<const ChangedMeanwhile*>(&e)) throw;
			if (i == 0) throw std::runtime_error(std::string(e.what()) + "; the old outputs are as they were");
			kept_ = true;  // the next run beside it puts the rest in
			throw std::runtime_error(std::string(e.what()) + "; the next run writing beside it puts the rest in place");
		}
	done_ = true;
}

void writeFileAtomically(const std::string& path, const std::string& bytes)
{
	OutputSet set;
	set.write({path, OutputKind::Text}, bytes);
	set.commit();
}

}  // namespace omnirange
