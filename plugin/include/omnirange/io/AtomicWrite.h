#pragma once
// Outputs are written to a temporary name beside the target and renamed when
// complete, so a failed run never leaves a half-written file that looks whole.

#include <functional>
#include <string>

namespace cv
{
class Mat;
}

namespace omnirange
{
/** Calls `write(tmp_path)` and renames tmp_path to `path` when it returns.
 * If `write` throws, the temporary file is removed and the error rethrown;
 * an existing `path` is left untouched. */
void writeAtomically(
	const std::string& path, const std::function<void(const std::string&)>& write);

/** Writes `bytes` to `path` atomically; throws std::runtime_error naming the
 * file on any I/O failure. */
void writeFileAtomically(const std::string& path, const std::string& bytes);

/** Encodes `image` in the format its path's extension names (.png, .jpg)
 * and writes it atomically. */
void writeImageAtomically(const std::string& path, const cv::Mat& image);

}  // namespace omnirange
