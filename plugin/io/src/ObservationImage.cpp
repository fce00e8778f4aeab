#include "omnirange/io/ObservationImage.h"

#include "JpegDecoder.h"
#include "PngDecoder.h"
#include "omnirange/config/OptionsTable.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <vector>
#include <stdexcept>

namespace omnirange
{
namespace
{
using Bytes = std::string_view;

unsigned be16(Bytes b, std::size_t at) { return (static_cast<unsigned char>(b[at]) << 8) | static_cast<unsigned char>(b[at + 1]); }
unsigned long be32(Bytes b, std::size_t at) { return (static_cast<unsigned long>(be16(b, at)) << 16) | be16(b, at + 2); }

/** A JPEG's size from its frame header, walking the markers; whether its
 * entropy-coded data reaches the end-of-image marker. Bytes after that
 * marker (a camera's trailer) are allowed. Returns why it is not whole, or "". */
std::string jpegProblem(Bytes b, unsigned long& width, unsigned long& height)
{
	std::size_t at = 2;
	while (at + 4 <= b.size())
	{
		if (static_cast<unsigned char>(b[at]) != 0xFF) return "not a JPEG: no marker at byte " + std::to_string(at);
		const unsigned char m = static_cast<unsigned char>(b[at + 1]);
		if (m == 0xFF) { ++at; continue; }  // fill byte
		if (m == 0xD9) return "";  // end of image before any scan: nothing to decode, imdecode says so
		const std::size_t length = be16(b, at + 2);
		if (length < 2 || at + 2 + length > b.size()) return "truncated: a JPEG segment runs past the file's end";
		const bool frame = m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
		if (frame && length >= 7) height = be16(b, at + 5), width = be16(b, at + 7);
		if (m == 0xDA)  // start of scan: in the coded data 0xFF is followed by 0 or a restart, so this is the end
			return b.find("\xFF\xD9", at + 2 + length) == std::string::npos ? "truncated: no JPEG end-of-image marker" : "";
		at += 2 + length;
	}
	return "truncated: no JPEG end-of-image marker";
}

unsigned long le32(Bytes b, std::size_t at)
{
	unsigned long v = 0;
	for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[at + i]);
	return v;
}

/** A PGM's, PPM's or PBM's size from its header ("P5 # comment\n W H MAX\n");
 * false if it is not one. For the binary grey and colour kinds (P5, P6),
 * `cut` says whether the pixels the header promises run past the file's end. */
bool pnmSize(Bytes b, unsigned long& width, unsigned long& height, bool& cut)
{
	if (b.size() < 3 || b[0] != 'P' || b[1] < '1' || b[1] > '6') return false;
	const bool binary = b[1] == '5' || b[1] == '6';
	std::size_t at = 2;
	unsigned long values[3] = {0, 0, 0};  // width, height, maximum (none for P1, P4)
	const int count = (b[1] == '1' || b[1] == '4') ? 2 : 3;
	for (int k = 0; k < count; ++k)
	{
		while (at < b.size() && (std::isspace(static_cast<unsigned char>(b[at])) || b[at] == '#'))
			if (b[at] == '#') at = b.find('\n', at) == std::string::npos ? b.size() : b.find('\n', at);
			else ++at;
		if (at >= b.size() || !std::isdigit(static_cast<unsigned char>(b[at]))) return false;
		for (; at < b.size() && std::isdigit(static_cast<unsigned char>(b[at])) && values[k] < 1000000000UL; ++at)
			values[k] = values[k] * 10 + static_cast<unsigned long>(b[at] - '0');
	}
	width = values[0], height = values[1];
	if (width * height > kMaxImagePixels) return true;  // refused by its size before anything is counted
	if (binary)
	{
		const unsigned long per_pixel = (b[1] == '6' ? 3 : 1) * (values[2] > 255 ? 2 : 1);
		cut = b.size() < at + 1 + width * height * per_pixel;  // one blank after the maximum
		return true;
	}
	// Plain (ASCII) kinds: a number per sample, a digit per bit in P1.
	const unsigned long needed = width * height * (b[1] == '3' ? 3 : 1);
	unsigned long found = 0;
	for (std::size_t i = at; i < b.size() && found < needed; ++i)
	{
		const bool digit = std::isdigit(static_cast<unsigned char>(b[i])) != 0;
		if (digit && (b[1] == '1' || i == at || !std::isdigit(static_cast<unsigned char>(b[i - 1])))) ++found;
	}
	cut = found < needed;
	return true;
}

/** A PAM's (P7) size from its header ("WIDTH 60\nHEIGHT 40\nDEPTH 3\nMAXVAL
 * 255\nENDHDR\n"); false if it is not one. `cut`: fewer bytes than it promises. */
bool pamSize(Bytes b, unsigned long& width, unsigned long& height, bool& cut)
{
	if (b.size() < 3 || b.substr(0, 3) != "P7\n") return false;
	unsigned long depth = 0, maxval = 0;
	std::size_t at = 3;
	for (std::size_t end; (end = b.find('\n', at)) != std::string::npos; at = end + 1)
	{
		const Bytes line = b.substr(at, end - at);
		if (line == "ENDHDR")
		{
			const unsigned long samples = width * height > kMaxImagePixels ? 0 : width * height * depth;
			cut = b.size() < end + 1 + samples * (maxval > 255 ? 2 : 1);
			return true;
		}
		const auto number = [&](const char* key, unsigned long& v) {
			const std::size_t n = std::strlen(key);
			if (line.substr(0, n) != key) return;
			v = 0;
			for (std::size_t i = n; i < line.size() && v < 1000000000UL; ++i)
				if (std::isdigit(static_cast<unsigned char>(line[i]))) v = v * 10 + static_cast<unsigned long>(line[i] - '0');
		};
		number("WIDTH ", width), number("HEIGHT ", height), number("DEPTH ", depth), number("MAXVAL ", maxval);
	}
	cut = true;  // no end of header
	return true;
}

/** Whether a BMP's pixel data run past the file's end: the rows an
 * uncompressed one promises, or the size a compressed one's header gives. */
bool bmpCut(Bytes b, unsigned long width, unsigned long height)
{
	if (b.size() < 54) return true;  // shorter than its two headers
	if (width * height > kMaxImagePixels) return false;  // refused by its size
	if (le32(b, 30) != 0) return b.size() < le32(b, 10) + le32(b, 34);  // compressed: biSizeImage bytes
	const unsigned long bits = static_cast<unsigned char>(b[28]) | (static_cast<unsigned char>(b[29]) << 8);
	const unsigned long stride = (width * bits + 31) / 32 * 4;
	return b.size() < le32(b, 10) + stride * height;
}

/** Why the bytes of an image file cannot be decoded whole (cut, or too many
 * pixels to decode), or "". A cut file would otherwise decode with grey rows
 * and only a libjpeg warning; a huge one would take minutes and gigabytes. */
std::string imageProblem(Bytes b)
{
	unsigned long width = 0, height = 0;
	std::string why;
	if (b.size() >= 2 && static_cast<unsigned char>(b[0]) == 0xFF && static_cast<unsigned char>(b[1]) == 0xD8)
		why = jpegProblem(b, width, height);
	else if (b.size() >= 24 && b.substr(1, 3) == "PNG")
	{
		width = be32(b, 16), height = be32(b, 20);
		const std::size_t from = b.size() > 16 ? b.size() - 16 : 0;
		if (b.find("IEND", from) == std::string::npos) why = "truncated: no PNG end chunk";
	}
	else if (b.size() >= 2 && b.substr(0, 2) == "BM")
	{
		if (b.size() < 54) return "truncated: shorter than a BMP's headers";
		width = le32(b, 18);
		const long h = static_cast<std::int32_t>(le32(b, 22));  // negative: stored top-down
		height = static_cast<unsigned long>(h < 0 ? -h : h);
		if (bmpCut(b, width, height)) why = "truncated: fewer pixel rows than its header says";
	}
	else if (bool cut = false; pamSize(b, width, height, cut))
	{
		if (cut) why = "truncated: fewer samples than its PAM header says";
	}
	else if (bool cut = false; pnmSize(b, width, height, cut))
	{
		if (cut && width * height <= kMaxImagePixels) why = "truncated: fewer pixels than its header says";
	}
	// "P5" and a blank: a PGM or PPM whose size is not two whole numbers (OpenCV would print its own lines).
	else if (b.size() >= 3 && b[0] == 'P' && b[1] >= '1' && b[1] <= '6' && std::isspace(static_cast<unsigned char>(b[2])))
		why = "malformed: its PGM/PPM header does not give a width and a height";
	if (why.empty() && width * height > kMaxImagePixels)
		why = std::to_string(width) + "x" + std::to_string(height) + ": more than " +
			  std::to_string(kMaxImagePixels / 1000000) + " megapixels";
	return why;
}

/** The bytes of the file `file` (`what` in errors), checked on what was
 * opened: a folder or a FIFO put in its place after it was looked at is
 * refused as such, not read as a size it does not have. */
std::vector<unsigned char> bytesOf(const std::string& file, const std::string& what)
{
	const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
	if (fd < 0) throw std::runtime_error(what + " is unreadable (" + std::strerror(errno) + ")");
	struct stat st{};
	if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
	{
		::close(fd);
		throw std::runtime_error(what + " is not a regular file");
	}
	std::vector<unsigned char> bytes(static_cast<std::size_t>(st.st_size));
	std::size_t got = 0;
	while (got < bytes.size())
	{
		const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
		if (n < 0 && errno == EINTR) continue;
		if (n <= 0) break;
		got += static_cast<std::size_t>(n);
	}
	::close(fd);
	if (got != bytes.size()) throw std::runtime_error(what + " is unreadable (it changed while it was read)");
	return bytes;
}
}  // namespace

bool isImageFileName(const std::string& file)
{
	std::string ext = std::filesystem::path(file).extension().string();
	for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
	for (const char* kind : {".jpg", ".jpeg", ".png", ".pgm", ".ppm", ".bmp"})
		if (ext == kind) return true;
	return false;
}

void decodeImageFile(const std::string& file, const std::string& label, int flags, const PixelBox& region, cv::Mat& image)
{
	const std::string what = "image '" + file + "'" + (label.empty() ? "" : " of " + label);
	std::error_code ec;
	if (const auto status = std::filesystem::status(file, ec); !std::filesystem::is_regular_file(status))
	{
		// A FIFO or a device would block or never end.
		if (std::filesystem::exists(status)) throw std::runtime_error(what + " is not a regular file");
		if (ec == std::errc::too_many_symbolic_link_levels)
			throw std::runtime_error(what + " is a link that leads back to itself, or one of more than 40 in a row (the " +
									 "system follows no more)");
		// A rawlog copied or renamed without its folder ("d.rawlog.bak" reads "d.rawlog.bak_Images").
		const auto folder = std::filesystem::path(file).parent_path();
		if (!folder.empty() && !std::filesystem::exists(folder, ec))
			throw std::runtime_error(what + " is missing: there is no folder '" + folder.string() +
									 "' (a rawlog reads its images from NAME_Images beside it, named as the rawlog is)");
		throw std::runtime_error(what + " is missing");
	}
	if (isKernelFile(file)) throw std::runtime_error(what + " is a file of the kernel's, not of data");
	const std::vector<unsigned char> bytes = bytesOf(file, what);
	if (bytes.empty()) throw std::runtime_error(what + " is empty");
	if (const std::string why = imageProblem(Bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
		!why.empty())
		throw std::runtime_error(what + " is " + why);
	const bool jpeg = bytes.size() >= 2 && bytes[0] == 0xFF && bytes[1] == 0xD8;
	const bool png = bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8) == 0;
	if ((jpeg || png) && (flags == cv::IMREAD_COLOR || flags == cv::IMREAD_GRAYSCALE))
	{
		const bool grey = flags == cv::IMREAD_GRAYSCALE;
		const std::string why = jpeg ? decodeJpeg(bytes.data(), bytes.size(), grey, image, region)
									 : decodePng(bytes.data(), bytes.size(), grey, image);
		if (!why.empty()) throw std::runtime_error(what + " is damaged: " + why);
	}
	else
		image.release();
	if (image.empty()) image = cv::imdecode(bytes, flags | cv::IMREAD_IGNORE_ORIENTATION);  // as decodeJpeg()
	if (image.empty()) throw std::runtime_error(what + " cannot be decoded: damaged, or not an image of its kind");
}

cv::Mat decodeImageFile(const std::string& file, const std::string& label, int flags, const PixelBox& region)
{
	cv::Mat image;
	decodeImageFile(file, label, flags, region, image);
	return image;
}

cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs, const PixelBox& region)
{
	cv::Mat img;
	if (obs.image.isExternallyStored())
	{
		// Read the file ourselves: CImage's lazy loading shares state between
		// threads and reports a missing file with a stack trace.
		return decodeImageFile(obs.image.getExternalStorageFileAbsolutePath(), obs.sensorLabel, cv::IMREAD_COLOR, region);
	}
	if (obs.image.isEmpty())  // MRPT's own access would throw a stack trace
		throw std::runtime_error("an empty " + obs.sensorLabel + " image stored in the rawlog");
	img = obs.image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	if (img.empty()) throw std::runtime_error("an empty " + obs.sensorLabel + " image");
	if (img.channels() == 1) cv::cvtColor(img, img, cv::COLOR_GRAY2BGR);
	return img.clone();
}

void decodeImage(const mrpt::obs::CObservationImage& obs, const CameraParams& cam, const PixelBox& region, cv::Mat& image)
{
	if (obs.image.isExternallyStored())
		decodeImageFile(obs.image.getExternalStorageFileAbsolutePath(), obs.sensorLabel, cv::IMREAD_COLOR, region, image);
	else
		image = decodeImage(obs);
	requireCameraSize(image, obs, cam);
}

cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs, const CameraParams& cam, const PixelBox& region)
{
	cv::Mat img;
	decodeImage(obs, cam, region, img);
	return img;
}

std::string sizeText(const cv::Size& size) { return std::to_string(size.width) + "x" + std::to_string(size.height); }

void requireCameraSize(const cv::Mat& img, const mrpt::obs::CObservationImage& obs, const CameraParams& cam)
{
	if (img.cols != cam.image_width || img.rows != cam.image_height)
		throw std::runtime_error(
			// With its folder, as every other image message names it.
			(obs.image.isExternallyStored() ? "image '" + obs.image.getExternalStorageFileAbsolutePath() + "'"
											: "an embedded " + obs.sensorLabel + " image") +
			" is " + sizeText(img.size()) + " but the camera is " + sizeText({cam.image_width, cam.image_height}));
}

}  // namespace omnirange
