#pragma once
// Facts about files that readers and writers check: where a rawlog's images
// are, where a link leads, whether a file changed, and the wording of a failed write.

#include <string>

namespace omnirange
{
/** NAME_Images beside NAME.rawlog (the folder MRPT's programs look in). */
std::string imagesDirFor(const std::string& rawlog_path);
/** The images folder a reader of `rawlog_path` uses: imagesDirFor() it, or,
 * when that is missing and the rawlog is a link, the one beside the file the
 * link leads to. */
std::string imagesDirToRead(const std::string& rawlog_path);
/** The file `path` leads to, links resolved (what a save into it writes). */
std::string fileLedTo(const std::string& path);
/** Where an output at `path` is written: through a link, what it leads to
 * (fileLedTo()); otherwise `path` as given. */
std::string writtenThrough(const std::string& path);
/** Throws naming both unless `path` leads to `was` still (fileLedTo() when
 * `since` began): a link made meanwhile would send a save to a file never given. */
void requireStillLeadsTo(const std::string& path, const std::string& was, const std::string& since);
/** What `path` is now, as "DEVICE:INODE:SIZE:MTIME" ("" if nothing): a file
 * written again or renamed in its place has another. */
std::string fileStateOf(const std::string& path);

/** "cannot write 'PATH' (REASON)": REASON from errno, or `otherwise`. */
std::string cannotWrite(const std::string& path, const std::string& otherwise = "");
/** Reads the gzip file `path` to its end; throws naming `what` unless it is
 * whole (a write that failed on a full disk leaves it cut short). */
void requireWholeGzipFile(const std::string& path, const std::string& what);

}  // namespace omnirange
