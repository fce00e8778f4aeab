#include "omnirange/config/Files.h"

#include <sys/stat.h>
#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace fs = std::filesystem;

namespace omnirange
{
namespace
{
std::string rawlogStem(const std::string& file_name)
{
	for (const std::string ext : {".rawlog.gz", ".rawlog"})
		if (file_name.size() > ext.size() && file_name.compare(file_name.size() - ext.size(), ext.size(), ext) == 0)
			return file_name.substr(0, file_name.size() - ext.size());
	return file_name;
}
}  // namespace

std::string imagesDirFor(const std::string& rawlog_path)
{
	const fs::path p(rawlog_path);
	return (p.parent_path() / (rawlogStem(p.filename().string()) + "_Images")).string();
}

std::string imagesDirToRead(const std::string& rawlog_path)
{
	const std::string beside = imagesDirFor(rawlog_path);
	std::error_code ec;
	if (fs::exists(fs::symlink_status(beside, ec)) || !fs::is_symlink(rawlog_path, ec)) return beside;
	return imagesDirFor(fs::weakly_canonical(rawlog_path, ec).string());
}

std::string fileLedTo(const std::string& path)
{
	std::error_code ec;
	return fs::weakly_canonical(path, ec).string();
}

std::string writtenThrough(const std::string& path)
{
	std::error_code ec;
	return fs::is_symlink(path, ec) ? fileLedTo(path) : path;
}

void requireStillLeadsTo(const std::string& path, const std::string& was, const std::string& since)
{
	if (const std::string now = fileLedTo(path); now != was)
		throw std::runtime_error("'" + path + "' now leads to '" + now + "', not to '" + was + "' as when " + since +
								 ": nothing was saved (run again)");
}

std::string fileStateOf(const std::string& path)
{
	struct stat st{};
	if (::stat(path.c_str(), &st) != 0) return "";
	return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
		   std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
}

std::string cannotWrite(const std::string& path, const std::string& otherwise)
{
	const std::string reason = errno != 0 ? std::strerror(errno) : otherwise;
	return "cannot write '" + path + "'" + (reason.empty() ? "" : " (" + reason + ")");
}

void requireWholeGzipFile(const std::string& path, const std::string& what)
{
	gzFile f = ::gzopen(path.c_str(), "rb");
	std::vector<char> buf(1 << 16);
	int n = 0, err = Z_OK;
	while (f && (n = ::gzread(f, buf.data(), static_cast<unsigned>(buf.size()))) > 0) continue;
	if (f) ::gzerror(f, &err);
	const bool whole = f && ::gzclose_r(f) == Z_OK && n == 0 && (err == Z_OK || err == Z_STREAM_END);
	if (!whole) throw std::runtime_error("'" + what + "' did not reach the disk whole (is the disk full?)");
}

}  // namespace omnirange
