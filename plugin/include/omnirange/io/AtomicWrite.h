#pragma once
// Outputs are written to a temporary name beside the target and renamed when
// complete, so a failed run never leaves a half-written file that looks whole.

#include <functional>
#include <string>
#include <vector>

namespace cv
{
class Mat;
}

namespace omnirange
{
/** Calls `write(tmp_path)`, syncs it to disk and renames it to `path`.
 * If `write` throws, the temporary file is removed and the error rethrown;
 * an existing `path` is left untouched. */
void writeAtomically(
	const std::string& path, const std::function<void(const std::string&)>& write);

/** fsync()s the file `path`; throws std::runtime_error naming `what` if it fails. */
void syncToDisk(const std::string& path, const std::string& what);

/** Reads the gzip file `path` to its end; throws std::runtime_error naming
 * `what` unless it is whole (a write that failed leaves it cut short). */
void requireWholeGzipFile(const std::string& path, const std::string& what);

/** Writes `bytes` to `path` atomically; throws std::runtime_error naming the
 * file on any I/O failure. */
void writeFileAtomically(const std::string& path, const std::string& bytes);

/** Encodes `image` in the format its path's extension names (.png, .jpg)
 * and writes it atomically. */
void writeImageAtomically(const std::string& path, const cv::Mat& image);

}  // namespace omnirange
