#pragma once
// Outputs are written to a temporary name beside the target and renamed when
// complete, so a failed run never leaves a half-written file that looks whole.

#include "omnirange/config/Temporaries.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace omnirange
{
/** `message` with every `from` (a temporary's or staging folder's path, which
 * a writer knows) replaced by `to` (the output the user asked for). */
std::string namingTheOutput(std::string message, const std::string& from, const std::string& to);

/** The file an output named `given` replaces: a link is written through
 * (the file it names is replaced, the link stays). Throws std::runtime_error
 * naming `given` when that file exists and is read-only by its mode bits
 * (root may write anything, but a user who made a file read-only meant it
 * to stay). */
std::string replacedFileOf(const std::string& given);

/** Why this process cannot rename or remove `path` in its folder, as the
 * system's reason ("" when it can): the folder is not writable, or it is
 * sticky (as /tmp) and neither `path` nor the folder is this user's. */
std::string whyCannotReplace(const std::string& path);
/** Gives the finished temporary `tmp` the mode of the file `target` it is
 * about to replace, if that exists. */
void keepModeOf(const std::string& target, const std::string& tmp);

/** Where a run writes `target` (a file or a folder) before renaming it into
 * place: ".NAME.tmp-PID" beside it. Hidden, and of a form nobody names a
 * backup, so that the next run can tell a killed run's leftover from a
 * user's "NAME.tmp-2024". */
std::string temporaryOf(const std::string& target);
/** Whether a file or folder name is of the forms runs name their
 * temporaries and leftovers (".NAME.tmp-PID", ".NAME.old-PID",
 * ".NAME.commit-PID", "NAME.staging-PID"): an output so named would be taken
 * for a killed run's leftover by a later run. */
bool isTemporaryName(const std::string& name);
/** Throws std::runtime_error when something is at `temporary`, the name
 * this run is about to make its `what` (after recoverLeftoversOf() took
 * what was a killed run's): it is the user's, and is neither emptied nor
 * replaced. In a container every run is PID 1, so the name is known in
 * advance. */
void requireNothingAt(const std::string& temporary, const std::string& what);
/** Renames `from` to `to` unless `to` exists (a name of the user's that
 * merely has the form of a run's temporary is never replaced); the
 * system's error otherwise (EEXIST when `to` is there). */
void renameNotReplacing(const std::string& from, const std::string& to, std::error_code& ec);

/** What `path` leads to now, as "DEVICE:INODE:SIZE:MTIME" ("" if nothing):
 * a file written again or renamed in its place has another (a link or a
 * chmod changes no part of it). */
std::string fileStateOf(const std::string& path);

/** A file that was read to be updated (an ini given keys, a page filled)
 * and changed before the update went in: another run's update, a user's
 * editor. Nothing was replaced; reading it again and updating that works. */
class ChangedMeanwhile : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

/** One file of a multi-file output, written in full to a temporary beside
 * `path` and synced, but renamed into place only by commit(): an output of
 * several files stages each, then commits them together (commitAll()), so
 * a failure while any is written leaves every old file whole. Destroyed
 * uncommitted (an error, an exception), it removes its temporary. */
class StagedFile
{
   public:
	/** Calls `write(tmp_path)` and syncs it; if `write` throws, the temporary
	 * is removed and the error rethrown. */
	StagedFile(const std::string& path, const std::function<void(const std::string&)>& write);
	StagedFile(const StagedFile&) = delete;
	StagedFile& operator=(const StagedFile&) = delete;
	~StagedFile();
	/** Renames the temporary to the path (under its folder's lock when
	 * replacing() was said). */
	void commit();
	/** It is an update of the file as it was in `state` (fileStateOf(),
	 * taken before it was read): commit() throws ChangedMeanwhile instead of
	 * replacing a file that has changed since, and removes the temporary. */
	void replacing(std::string state) { read_state_ = std::move(state); }

   private:
	friend class FileSetCommit;
	/** Throws ChangedMeanwhile (the temporary removed) if the file is no longer as read. */
	void requireAsRead();
	std::string path_, tmp_;
	std::optional<std::string> read_state_;
	bool committed_{false};
};

/** Holds the folder `path` is in locked (flock) while it lives: two runs
 * putting outputs in place there take turns, so neither sees the other's
 * half-done renames. Every commit of ours takes it; an interrupt meanwhile
 * waits for it to end (temporaries::InterruptsDeferred). */
class FolderLock
{
   public:
	explicit FolderLock(const std::string& path);
	~FolderLock();
	/** The folder locked for `path`: its parent, links resolved. */
	static std::string folderOf(const std::string& path);
	FolderLock(const FolderLock&) = delete;
	FolderLock& operator=(const FolderLock&) = delete;

   private:
	std::string folder_;
	int fd_{-1};
	bool owner_{false};  ///< false: a commit this one is inside holds the folder
	std::unique_ptr<temporaries::InterruptsDeferred> deferred_;
};

/** The files of one output put in place as one. put(): a journal beside
 * each (.NAME.commit-PID) names the set, where each old file goes aside
 * (.NAME.old-PID) and the new file's inode; every old file goes aside, every
 * new one in (every folder of the set locked meanwhile). finish(): the
 * journals go, then the old files. undo() (or a put() that fails, or
 * destruction before finish()): every new file out, every old one back;
 * the journals stay if that fails, for the next run. A run killed in between
 * leaves its journals: every reader of a file of the set refuses it
 * (requireWholeSet()) and the next run writing one of them settles the set
 * first (recoverSetOf()): the new one if every new file was in, else the old. */
class FileSetCommit
{
   public:
	explicit FileSetCommit(std::vector<StagedFile*> files);
	~FileSetCommit();
	FileSetCommit(const FileSetCommit&) = delete;
	FileSetCommit& operator=(const FileSetCommit&) = delete;
	void put();
	void finish();
	/** Puts every old file back; "" or what could not be (the journals then stay). */
	std::string undo();

   private:
	std::vector<StagedFile*> files_;
	std::vector<std::string> asides_, journals_;
	std::vector<std::unique_ptr<FolderLock>> locks_;
	std::size_t aside_{0}, in_{0};
	bool finished_{false};
};

/** put() and finish() at once. */
void commitAll(const std::vector<StagedFile*>& files);
/** The files of `owned`, for commitAll(). */
template <class Owner>
std::vector<StagedFile*> pointersTo(const std::vector<Owner>& owned)
{
	std::vector<StagedFile*> files;
	for (const auto& f : owned) files.push_back(&*f);
	return files;
}

/** Throws std::runtime_error naming `path` when a run is putting it in
 * place with other files, or was killed doing so (its journal is beside
 * it): the set may be half of one run's and half of another's. */
void requireWholeSet(const std::string& path);

/** When a run that is over left a journal beside `path` (FileSetCommit):
 * if every new file of its set is in (it was killed finishing), its old
 * files and journals go; else every file of its set goes back as it was (an
 * old one from aside, a new one that had no old one removed; only a file
 * whose inode the journal recorded, not one put there since), and its
 * journals go. Either way the set is one run's whole, never a mix. Throws
 * std::runtime_error when the journal's run is still going: another run is
 * putting `path` in place now. */
void recoverSetOf(const std::string& path);

/** Calls `write(tmp_path)`, syncs it to disk and renames it to `path`.
 * If `write` throws, the temporary file is removed and the error rethrown;
 * an existing `path` is left untouched. */
void writeAtomically(
	const std::string& path, const std::function<void(const std::string&)>& write);

/** fsync()s the file `path`; throws std::runtime_error naming `what` if it fails. */
void syncToDisk(const std::string& path, const std::string& what);
/** "cannot write 'PATH' (REASON)": REASON the system's, as the open or write
 * that just failed left it in errno (a full disk, a read-only file system,
 * no permission), or `otherwise` when it left none. */
std::string cannotWrite(const std::string& path, const std::string& otherwise = "");

/** The CRC-32 of what the file `path` holds, uncompressed (gzip or not: the
 * same rawlog compressed or not has one), or nullopt unless it reads whole. */
std::optional<std::uint32_t> contentCrcOf(const std::string& path);
/** Reads the gzip file `path` to its end; throws std::runtime_error naming
 * `what` unless it is whole (a write that failed leaves it cut short).
 * Returns contentCrcOf() it. */
std::uint32_t requireWholeGzipFile(const std::string& path, const std::string& what);

/** Writes `bytes` to `path` atomically; throws std::runtime_error naming the
 * file on any I/O failure. */
void writeFileAtomically(const std::string& path, const std::string& bytes);
/** writeFileAtomically() as an update of the file read in `read_state`
 * (StagedFile::replacing()): throws ChangedMeanwhile if it changed since. */
void updateFileAtomically(const std::string& path, const std::string& bytes, const std::string& read_state);
/** A StagedFile's writer of `bytes` (both must outlive the StagedFile's
 * constructor), its errors naming `path`. */
std::function<void(const std::string&)> writerOf(const std::string& path, const std::string& bytes);

}  // namespace omnirange
