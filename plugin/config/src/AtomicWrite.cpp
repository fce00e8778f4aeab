#include "omnirange/config/AtomicWrite.h"

#include "omnirange/config/Temporaries.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace omnirange
{
std::string namingTheOutput(std::string message, const std::string& from, const std::string& to)
{
	for (auto at = message.find(from); at != std::string::npos; at = message.find(from, at + to.size()))
		message.replace(at, from.size(), to);
	return message;
}

std::string replacedFileOf(const std::string& given)
{
	namespace fs = std::filesystem;
	std::error_code ec;
	const std::string path = fs::is_symlink(given, ec) ? fs::weakly_canonical(given, ec).string() : given;
	if (fs::is_regular_file(path, ec))
	{
		const auto mode = fs::status(path, ec).permissions();
		if (::access(path.c_str(), W_OK) != 0 || (mode & fs::perms::owner_write) == fs::perms::none)
			throw std::runtime_error("'" + given + "' is read-only: refusing to replace it");
		if (const std::string why = whyCannotReplace(path); !why.empty())
			throw std::runtime_error("'" + given + "' cannot be replaced (" + why + ")");
	}
	return path;
}

std::string whyCannotReplace(const std::string& path)
{
	const std::filesystem::path p(path);
	const std::string parent = p.parent_path().empty() ? "." : p.parent_path().string();
	if (::access(parent.c_str(), W_OK | X_OK) != 0) return std::strerror(errno);
	struct stat folder{}, file{};
	if (::stat(parent.c_str(), &folder) != 0 || ::lstat(path.c_str(), &file) != 0) return "";
	const uid_t me = ::geteuid();
	if ((folder.st_mode & S_ISVTX) && me != 0 && file.st_uid != me && folder.st_uid != me)
		return "it belongs to another user, in a folder where only its owner may rename it";
	return "";
}

void keepModeOf(const std::string& target, const std::string& tmp)
{
	namespace fs = std::filesystem;
	std::error_code ec;
	if (fs::is_regular_file(target, ec)) fs::permissions(tmp, fs::status(target, ec).permissions());
}

std::string temporaryOf(const std::string& target)
{
	const std::filesystem::path t(target);
	return (t.parent_path() / ("." + t.filename().string() + ".tmp-" + std::to_string(static_cast<long>(::getpid()))))
		.string();
}

bool isTemporaryName(const std::string& name)
{
	// "...<what>-<digits>": a run's process id after what the run names.
	const auto dash = name.rfind('-');
	if (dash == std::string::npos || dash + 1 == name.size() ||
		name.find_first_not_of("0123456789", dash + 1) != std::string::npos)
		return false;
	const auto dot = name.rfind('.', dash);
	if (dot == std::string::npos) return false;
	const std::string what = name.substr(dot + 1, dash - dot - 1);
	return what == "staging" || (name.front() == '.' && dot > 0 && (what == "tmp" || what == "old" || what == "commit"));
}

void requireNothingAt(const std::string& temporary, const std::string& what)
{
	struct stat st{};
	if (::lstat(temporary.c_str(), &st) == 0)
		throw std::runtime_error("'" + temporary + "', the name of this run's " + what + ", is taken by what is not " +
								 "this program's to remove: move it away");
}

void renameNotReplacing(const std::string& from, const std::string& to, std::error_code& ec)
{
	ec.clear();
	if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return;
	if (errno != EINVAL) return ec.assign(errno, std::generic_category());
	// A file system without the flag: looked at first, then renamed (not one step, but no worse than before).
	struct stat st{};
	if (::lstat(to.c_str(), &st) == 0) return ec.assign(EEXIST, std::generic_category());
	if (::rename(from.c_str(), to.c_str()) != 0) ec.assign(errno, std::generic_category());
}

StagedFile::StagedFile(const std::string& given, const std::function<void(const std::string&)>& write)
	: path_(replacedFileOf(given)), tmp_(temporaryOf(path_))
{
	requireNothingAt(tmp_, "temporary file");
	temporaries::add(tmp_);
	try
	{
		write(tmp_);
		keepModeOf(path_, tmp_);
		syncToDisk(tmp_, path_);
	}
	catch (const std::exception& e)
	{
		std::remove(tmp_.c_str());
		temporaries::forget(tmp_);
		// A writer knows only the temporary's name; the user knows the file they asked for.
		if (std::string(e.what()).find(tmp_) == std::string::npos) throw;
		throw std::runtime_error(namingTheOutput(e.what(), tmp_, given));
	}
	catch (...)
	{
		std::remove(tmp_.c_str());
		temporaries::forget(tmp_);
		throw;
	}
}

StagedFile::~StagedFile()
{
	if (committed_) return;
	std::remove(tmp_.c_str());
	temporaries::forget(tmp_);
}

std::string fileStateOf(const std::string& path)
{
	struct stat st{};
	if (::stat(path.c_str(), &st) != 0) return "";
	return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
		   std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
}

void StagedFile::requireAsRead()
{
	if (!read_state_ || fileStateOf(path_) == *read_state_) return;
	committed_ = true;
	std::remove(tmp_.c_str());
	temporaries::forget(tmp_);
	throw ChangedMeanwhile("'" + path_ + "' changed while this run updated it (another run, or an editor): " +
						   "nothing of this run went in; run it again");
}

void StagedFile::commit()
{
	if (committed_) return;
	// An update: no other run's goes in between the check and the rename.
	const std::unique_ptr<FolderLock> lock = read_state_ ? std::make_unique<FolderLock>(path_) : nullptr;
	requireAsRead();
	committed_ = true;
	// Forgotten once renamed: an interrupt before that removes it (after, its name is gone: nothing to remove).
	const bool renamed = std::rename(tmp_.c_str(), path_.c_str()) == 0;
	const std::string reason = renamed ? "" : std::strerror(errno);
	if (!renamed) std::remove(tmp_.c_str());
	temporaries::forget(tmp_);
	if (!renamed) throw std::runtime_error("cannot put the new '" + path_ + "' in place (" + reason + ")");
}

namespace
{
/** The folders this process holds locked: a commit inside another (a
 * simulation's true maps inside its rawlog's) must not wait for itself,
 * as flock() would make it on a second descriptor. */
std::set<std::string>& heldFolders()
{
	static std::set<std::string> held;
	return held;
}
std::mutex held_mutex;

/** [s] How long another run's commit may hold a folder before the wait for it is said. */
constexpr double kQuietWait = 2.0;

/** Tries to lock the folder `fd` for kQuietWait: true if another run still
 * holds it then (false: locked, or no lock to be had). */
bool heldElsewhere(int fd)
{
	const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(kQuietWait);
	while (::flock(fd, LOCK_EX | LOCK_NB) != 0)
	{
		if (errno != EWOULDBLOCK) return false;
		if (std::chrono::steady_clock::now() > until) return true;
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
	return false;
}
}  // namespace

std::string FolderLock::folderOf(const std::string& path)
{
	namespace fs = std::filesystem;
	std::error_code ec;
	const fs::path given = fs::path(path).parent_path().empty() ? "." : fs::path(path).parent_path();
	return fs::weakly_canonical(fs::absolute(given, ec), ec).string();
}

FolderLock::FolderLock(const std::string& path) : folder_(folderOf(path))
{
	{
		const std::lock_guard<std::mutex> guard(held_mutex);
		owner_ = heldFolders().insert(folder_).second;  // else held already, by a commit this one is inside
	}
	if (!owner_) return;
	fd_ = ::open(folder_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	// Without a lock (a folder that cannot be opened so) the run goes on as before: the renames say what fails.
	if (fd_ >= 0 && heldElsewhere(fd_))
	{
		// Another run's commit takes a moment; one that does not end was stopped (Ctrl+Z, a debugger).
		temporaries::warn("waiting for another run, which is putting its output into '" + folder_ +
						  "' (if it was stopped, this one waits for it; Ctrl+C leaves nothing of this one there)");
		::flock(fd_, LOCK_EX);
	}
	deferred_ = std::make_unique<temporaries::InterruptsDeferred>();  // once it is this run's turn
}

FolderLock::~FolderLock()
{
	if (!owner_) return;
	if (fd_ >= 0) ::close(fd_);  // closing releases the lock
	const std::lock_guard<std::mutex> guard(held_mutex);
	heldFolders().erase(folder_);
}

namespace
{
namespace fs = std::filesystem;

/** Beside `target`, what a set commit names after it: ".NAME.commit-PID", ".NAME.old-PID". */
std::string besideAs(const std::string& target, const std::string& what, const std::string& pid)
{
	const fs::path t(target);
	return (t.parent_path() / ("." + t.filename().string() + "." + what + "-" + pid)).string();
}

/** One file of a set a journal names: where it goes, where its old file went
 * ("" if it had none), and the inode of the new file (which a rename keeps). */
struct SetFile
{
	std::string target, aside, inode;
};

std::vector<SetFile> setIn(const std::string& journal)
{
	std::ifstream f(journal);
	std::vector<SetFile> set;
	std::string line;
	std::getline(f, line);  // the run
	while (std::getline(f, line))
	{
		SetFile file;
		std::istringstream fields(line);
		if (std::getline(fields, file.target, '\t') && std::getline(fields, file.aside, '\t') && std::getline(fields, file.inode))
			set.push_back(file);
	}
	return set;
}

/** The journal of a set `target` is in, if any: its own (.NAME.commit-PID
 * beside it), or one beside it that names it (its own removed first by a run
 * killed finishing); its path, and its run ("PID START"). */
std::pair<std::string, std::string> journalOf(const std::string& target)
{
	const fs::path t(target);
	const fs::path dir = t.parent_path().empty() ? "." : t.parent_path();
	const std::string own = "." + t.filename().string() + ".commit-";
	const auto runOf = [](const fs::path& journal) {
		std::ifstream f(journal);
		std::string run;
		std::getline(f, run);
		return run.rfind("run ", 0) == 0 ? run.substr(4) : std::string();
	};
	std::error_code ec;
	std::vector<fs::path> others;
	for (const auto& e : fs::directory_iterator(dir, ec))
	{
		// ".NAME.commit-PID" only: not a journal's own temporary ("..NAME.commit-PID.tmp-PID"), which names no set yet.
		const std::string name = e.path().filename().string();
		const auto at = name.rfind(".commit-");
		if (name.front() != '.' || at == std::string::npos || at + 8 == name.size() ||
			name.find_first_not_of("0123456789", at + 8) != std::string::npos || !fs::is_regular_file(e.symlink_status(ec)))
			continue;
		if (name.rfind(own, 0) != 0)
			others.push_back(e.path());
		else if (const std::string run = runOf(e.path()); !run.empty())
			return {e.path().string(), run};
	}
	for (const auto& journal : others)
		for (const auto& f : setIn(journal.string()))
			if (std::error_code same; f.target == target || fs::equivalent(f.target, target, same))
				if (const std::string run = runOf(journal); !run.empty()) return {journal.string(), run};
	return {};
}

/** The inode of `path` ("" if there is none): what tells a run's new file from one put there since. */
std::string inodeOf(const std::string& path)
{
	struct stat st{};
	return ::lstat(path.c_str(), &st) == 0 ? std::to_string(st.st_ino) : "";
}
}  // namespace

FileSetCommit::FileSetCommit(std::vector<StagedFile*> files) : files_(std::move(files))
{
	// Every folder of the set, in one order (of the folders locked, links resolved), so that two runs with sets
	// over the same folders, however named, cannot each wait for the other.
	std::map<std::string, std::string> folders;  // the folder locked, a file of the set in it
	for (const auto* f : files_) folders.emplace(FolderLock::folderOf(f->path_), f->path_);
	for (const auto& [folder, path] : folders) locks_.push_back(std::make_unique<FolderLock>(path));
}

FileSetCommit::~FileSetCommit()
{
	if (!finished_ && (aside_ > 0 || in_ > 0)) undo();
}

void FileSetCommit::put()
{
	if (files_.empty()) return;
	const std::string run = temporaries::thisRun(), pid = run.substr(0, run.find(' '));
	std::string journal = "run " + run + "\n";
	for (const auto* f : files_)
	{
		// The journal holds a file a line, its fields split by tabs.
		if (f->path_.find_first_of("\t\n\r") != std::string::npos)
			throw std::runtime_error("cannot put a file whose path holds a tab or a line break in place with others (the " +
									 std::string("journal naming them would read back wrong)"));
		std::error_code ec;
		asides_.push_back(fs::exists(fs::symlink_status(f->path_, ec)) ? besideAs(f->path_, "old", pid) : "");
		journal += f->path_ + "\t" + asides_.back() + "\t" + inodeOf(f->tmp_) + "\n";
	}
	for (auto* f : files_) f->requireAsRead();  // under the locks: nothing moved yet
	// Not temporaries: an interrupt mid-way leaves them, for readers to refuse and the next run to undo.
	for (const auto* f : files_)
	{
		journals_.push_back(besideAs(f->path_, "commit", pid));
		writeFileAtomically(journals_.back(), journal);
	}
	try
	{
		for (; aside_ < files_.size(); ++aside_)
			if (!asides_[aside_].empty())
			{
				std::error_code ec;
				renameNotReplacing(files_[aside_]->path_, asides_[aside_], ec);
				if (ec)
					throw std::runtime_error(ec.value() == EEXIST ? "'" + asides_[aside_] + "' is in the way: move it away"
																  : ec.message());
			}
		for (; in_ < files_.size(); ++in_) fs::rename(files_[in_]->tmp_, files_[in_]->path_);
	}
	catch (const std::exception& e)
	{
		const StagedFile* failed = aside_ < files_.size() ? files_[aside_] : files_[in_];
		const std::string left = undo();
		const auto* fe = dynamic_cast<const fs::filesystem_error*>(&e);
		throw std::runtime_error("cannot put '" + failed->path_ + "' in place (" + (fe ? fe->code().message() : e.what()) +
								 "); " + (left.empty() ? "every file of this output is as it was" : left));
	}
}

std::string FileSetCommit::undo()
{
	std::error_code ec;
	bool whole = true;
	for (std::size_t i = 0; i < in_; ++i) fs::remove(files_[i]->path_, ec), whole = whole && !ec;
	for (std::size_t i = 0; i < aside_; ++i)
		if (!asides_[i].empty()) fs::rename(asides_[i], files_[i]->path_, ec), whole = whole && !ec;
	aside_ = in_ = 0;
	finished_ = true;
	if (!whole)
		return "not every old file could be put back: they are beside their names as .NAME.old-PID, and the next run "
			   "of this program puts them back";
	for (const auto& j : journals_) fs::remove(j, ec);
	return "";
}

void FileSetCommit::finish()
{
	for (auto* f : files_) f->committed_ = true, temporaries::forget(f->tmp_);
	finished_ = true;
	// The journals first: while one is there, the old files it names are too.
	std::error_code ec;
	for (const auto& j : journals_) fs::remove(j, ec);
	for (const auto& a : asides_)
		if (!a.empty()) fs::remove(a, ec);
}

void commitAll(const std::vector<StagedFile*>& files)
{
	FileSetCommit set(files);
	set.put();
	set.finish();
}

void requireWholeSet(const std::string& path)
{
	if (const auto [journal, run] = journalOf(path); !journal.empty())
		throw std::runtime_error("'" + path + "' may be one of a set of files a run (" + run.substr(0, run.find(' ')) +
								 ") was putting in place and had not finished: the others may be of another run (if " +
								 "it was killed, run that program again)");
}

void recoverSetOf(const std::string& path)
{
	const auto [journal, run] = journalOf(path);
	if (journal.empty()) return;
	const auto space = run.find(' ');
	const std::string pid = run.substr(0, space);
	if (!temporaries::runGone(pid, space == std::string::npos ? "" : run.substr(space + 1)))
		throw std::runtime_error("'" + path + "' is being put in place by another run (" + pid + ") now");
	std::error_code ec;
	const auto set = setIn(journal);
	// Each member's journal, and what is left of one the run was killed writing (its temporary).
	const auto removeJournals = [&] {
		for (const auto& f : set)
		{
			const std::string own = besideAs(f.target, "commit", pid), cut = besideAs(own, "tmp", pid);
			fs::remove(own, ec);
			if (fs::is_regular_file(fs::symlink_status(cut, ec))) fs::remove(cut, ec);
		}
	};
	// Every new file in: it was killed finishing (its journals going, then its old files), and the set is the new one.
	const bool all_in = std::all_of(set.begin(), set.end(),
									[](const SetFile& f) { return !f.inode.empty() && inodeOf(f.target) == f.inode; });
	if (all_in)
	{
		removeJournals();
		for (const auto& f : set)
			if (!f.aside.empty()) fs::remove(f.aside, ec);
		temporaries::warn("a run (" + pid + ") was killed while it finished putting '" + path + "'" +
						  (set.size() > 1 ? " and " + std::to_string(set.size() - 1) + " other file(s)" : "") +
						  " in place: its new files stay");
		return;
	}
	for (const auto& f : set)
	{
		// Only what that run put in is taken out: a file put there since is someone's.
		const std::string now = inodeOf(f.target);
		const bool theirs = !now.empty() && now == f.inode;
		// Its new file not yet put in: still its temporary.
		if (const std::string tmp = besideAs(f.target, "tmp", pid); !f.inode.empty() && inodeOf(tmp) == f.inode)
			fs::remove(tmp, ec);
		std::error_code failed;
		if (!f.aside.empty() && fs::exists(fs::symlink_status(f.aside, ec)) && (now.empty() || theirs))
			fs::rename(f.aside, f.target, failed);
		else if (f.aside.empty() && theirs)
			fs::remove(f.target, failed);  // new in that set: it had no old file
		// The journals stay while an old file is still aside: they say where it is.
		if (failed)
			throw std::runtime_error("cannot put back '" + f.target + "', which a run (" + pid + ") was replacing when " +
									 "it was killed: " + (f.aside.empty() ? "" : "the old one is in '" + f.aside + "'; ") +
									 failed.message());
	}
	removeJournals();
	temporaries::warn("a run (" + pid + ") was killed while it put '" + path + "'" +
					  (set.size() > 1 ? " and " + std::to_string(set.size() - 1) + " other file(s)" : "") +
					  " in place: what was there before is back");
}

void writeAtomically(
	const std::string& given, const std::function<void(const std::string&)>& write)
{
	StagedFile(given, write).commit();
}

void syncToDisk(const std::string& path, const std::string& what)
{
	const int fd = ::open(path.c_str(), O_RDONLY);
	const bool ok = fd >= 0 && ::fsync(fd) == 0;
	if (fd >= 0) ::close(fd);
	if (!ok) throw std::runtime_error("cannot write '" + what + "' to disk: " + std::strerror(errno));
}

std::string cannotWrite(const std::string& path, const std::string& otherwise)
{
	const std::string reason = errno != 0 ? std::strerror(errno) : otherwise;
	return "cannot write '" + path + "'" + (reason.empty() ? "" : " (" + reason + ")");
}

std::optional<std::uint32_t> contentCrcOf(const std::string& path)
{
	gzFile f = ::gzopen(path.c_str(), "rb");
	if (!f) return std::nullopt;
	std::vector<unsigned char> buf(1 << 16);
	uLong crc = ::crc32(0L, Z_NULL, 0);
	int n = 0;
	while ((n = ::gzread(f, buf.data(), static_cast<unsigned>(buf.size()))) > 0)
		crc = ::crc32(crc, buf.data(), static_cast<uInt>(n));
	int err = Z_OK;
	::gzerror(f, &err);
	const bool closed = ::gzclose_r(f) == Z_OK;
	if (n != 0 || (err != Z_OK && err != Z_STREAM_END) || !closed) return std::nullopt;
	return static_cast<std::uint32_t>(crc);
}

std::uint32_t requireWholeGzipFile(const std::string& path, const std::string& what)
{
	const auto crc = contentCrcOf(path);
	if (!crc) throw std::runtime_error("'" + what + "' did not reach the disk whole (is the disk full?)");
	return *crc;
}

std::function<void(const std::string&)> writerOf(const std::string& path, const std::string& bytes)
{
	return [&path, &bytes](const std::string& tmp) {
		errno = 0;
		std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
		if (!f) throw std::runtime_error(cannotWrite(path));
		f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
		f.close();
		if (!f) throw std::runtime_error(cannotWrite(path, "is the disk full?"));
	};
}

void writeFileAtomically(const std::string& path, const std::string& bytes)
{
	writeAtomically(path, writerOf(path, bytes));
}

void updateFileAtomically(const std::string& path, const std::string& bytes, const std::string& read_state)
{
	StagedFile staged(path, writerOf(path, bytes));
	staged.replacing(read_state);
	staged.commit();
}
}  // namespace omnirange
