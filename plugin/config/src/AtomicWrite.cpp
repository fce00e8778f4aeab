#include "omnirange/config/AtomicWrite.h"

#include "omnirange/config/Temporaries.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <opencv2/imgcodecs.hpp>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
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

StagedFile::StagedFile(const std::string& given, const std::function<void(const std::string&)>& write)
	: path_(replacedFileOf(given)), tmp_(temporaryOf(path_))
{
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

void StagedFile::commit()
{
	if (committed_) return;
	committed_ = true;
	temporaries::forget(tmp_);
	if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
	{
		const std::string reason = std::strerror(errno);
		std::remove(tmp_.c_str());
		throw std::runtime_error("cannot put the new '" + path_ + "' in place (" + reason + ")");
	}
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

void requireWholeGzipFile(const std::string& path, const std::string& what)
{
	gzFile f = ::gzopen(path.c_str(), "rb");
	if (!f) throw std::runtime_error("cannot read back '" + what + "'");
	std::vector<char> buf(1 << 16);
	int n = 0;
	while ((n = ::gzread(f, buf.data(), static_cast<unsigned>(buf.size()))) > 0)
	{
	}
	int err = Z_OK;
	::gzerror(f, &err);
	const bool closed = ::gzclose_r(f) == Z_OK;
	const bool whole = n == 0 && (err == Z_OK || err == Z_STREAM_END) && closed;
	if (!whole) throw std::runtime_error("'" + what + "' did not reach the disk whole (is the disk full?)");
}

namespace
{
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

std::string encoded(const std::string& path, const cv::Mat& image)
{
	const auto dot = path.rfind('.');
	std::vector<uchar> buf;
	if (dot == std::string::npos || !cv::imencode(path.substr(dot), image, buf))
		throw std::runtime_error("cannot encode image '" + path + "'");
	return std::string(buf.begin(), buf.end());
}
}  // namespace

void writeFileAtomically(const std::string& path, const std::string& bytes)
{
	writeAtomically(path, writerOf(path, bytes));
}

void writeImageAtomically(const std::string& path, const cv::Mat& image)
{
	writeFileAtomically(path, encoded(path, image));
}

StagedFile stageImage(const std::string& path, const cv::Mat& image)
{
	const std::string bytes = encoded(path, image);
	return StagedFile(path, writerOf(path, bytes));
}
}  // namespace omnirange
