#include "omnirange/core/ColourHistogram.h"

#include <omnirange/config/Output.h>
#include "omnirange/config/OptionsTable.h"

#include <opencv2/core.hpp>
#include <zlib.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace omnirange
{
namespace
{
// File layout, all integers little-endian:
//   8 bytes magic "OMNIHIST", u32 version, u32 colour space, u32 bins,
//   u64 total, u64 counts[bins^3], u32 CRC-32 of every byte before it.
constexpr char kMagic[8] = {'O', 'M', 'N', 'I', 'H', 'I', 'S', 'T'};
constexpr std::size_t kHeaderBytes = 8 + 4 + 4 + 4 + 8;

void putLE(std::string& out, std::uint64_t v, int bytes)
{
	for (int i = 0; i < bytes; ++i)
		out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

std::uint64_t getLE(const std::string& in, std::size_t at, int bytes)
{
	std::uint64_t v = 0;
	for (int i = 0; i < bytes; ++i)
		v |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[at + i]))
			 << (8 * i);
	return v;
}

std::uint32_t crcOf(const std::string& bytes, std::size_t len)
{
	return static_cast<std::uint32_t>(::crc32(
		0L, reinterpret_cast<const Bytef*>(bytes.data()),
		static_cast<uInt>(len)));
}
}  // namespace

ColourHistogram::ColourHistogram(ColourSpace space, int bins)
	: binner_(space, bins), counts_(binner_.binCount(), 0)
{
}

void ColourHistogram::addImage(const cv::Mat& bgr, const cv::Mat& mask)
{
	if (bgr.type() != CV_8UC3)
		throw std::invalid_argument("histogram training needs an 8-bit BGR image");
	if (mask.type() != CV_8UC1 || mask.size() != bgr.size())
		throw std::invalid_argument(
			"histogram training mask must be 8-bit with the image's size");
	for (int r = 0; r < bgr.rows; ++r)
	{
		const auto* px = bgr.ptr<std::uint8_t>(r);
		const auto* m = mask.ptr<std::uint8_t>(r);
		for (int c = 0; c < bgr.cols; ++c)
			if (m[c]) addPixel(px + 3 * c);
	}
}

void ColourHistogram::merge(const ColourHistogram& other)
{
	if (other.space() != space() || other.binsPerChannel() != binsPerChannel())
		throw std::invalid_argument(
			"cannot merge histograms of different colour space or bins");
	for (std::size_t i = 0; i < counts_.size(); ++i) counts_[i] += other.counts_[i];
	total_ += other.total_;
}

double ColourHistogram::probability(std::uint32_t bin) const
{
	return total_ == 0 ? 0.0
					   : static_cast<double>(counts_.at(bin)) /
			static_cast<double>(total_);
}

std::vector<double> ColourHistogram::smoothedProbabilities(double sigma) const
{
	if (!kSmoothingRange.contains(sigma))
		throw std::invalid_argument("histogram smoothing must be " + kSmoothingRange.text() + " bins");
	const std::uint32_t n = binner_.binCount();
	std::vector<double> p(n);
	for (std::uint32_t b = 0; b < n; ++b) p[b] = probability(b);
	if (sigma == 0 || empty()) return p;
	const int radius = static_cast<int>(std::ceil(2.5 * sigma));
	std::vector<double> kernel(2 * radius + 1);
	double sum = 0;
	for (int k = -radius; k <= radius; ++k) sum += kernel[k + radius] = std::exp(-0.5 * k * k / (sigma * sigma));
	for (double& w : kernel) w /= sum;
	// Separable: along each channel in turn (bin = c0 * bins^2 + c1 * bins + c2).
	const int bins = binsPerChannel();
	std::vector<double> out(n);
	for (const int stride : {bins * bins, bins, 1})
	{
		for (std::uint32_t b = 0; b < n; ++b)
		{
			const int c = static_cast<int>(b / stride) % bins;  // this bin's index along the channel
			double v = 0;
			for (int k = std::max(-radius, -c); k <= std::min(radius, bins - 1 - c); ++k)
				v += kernel[k + radius] * p[b + static_cast<std::int64_t>(k) * stride];
			out[b] = v;
		}
		p.swap(out);
	}
	return p;
}

std::string ColourHistogram::serialize() const
{
	std::string out(kMagic, sizeof(kMagic));
	putLE(out, kFileVersion, 4);
	putLE(out, static_cast<std::uint32_t>(space()), 4);
	putLE(out, static_cast<std::uint32_t>(binsPerChannel()), 4);
	putLE(out, total_, 8);
	for (auto c : counts_) putLE(out, c, 8);
	putLE(out, crcOf(out, out.size()), 4);
	return out;
}

std::size_t ColourHistogram::serializedSize(const std::string& in, const std::string& what)
{
	if (in.size() < kHeaderBytes + 4 || in.compare(0, sizeof(kMagic), kMagic, sizeof(kMagic)) != 0)
		throw std::runtime_error("histogram file '" + what + "': not an omnirange histogram file");
	const auto bins = getLE(in, 16, 4);
	if (bins < 1 || bins > 256)
		throw std::runtime_error("histogram file '" + what + "': impossible bin count " + std::to_string(bins));
	return kHeaderBytes + 8 * bins * bins * bins + 4;
}

ColourHistogram ColourHistogram::deserialize(
	const std::string& in, const std::string& what)
{
	const auto fail = [&](const std::string& why) {
		return std::runtime_error("histogram file '" + what + "': " + why);
	};
	if (in.size() < kHeaderBytes + 4 ||
		in.compare(0, sizeof(kMagic), kMagic, sizeof(kMagic)) != 0)
		throw fail("not an omnirange histogram file");
	const auto version = getLE(in, 8, 4);
	if (version != kFileVersion)
		throw fail(
			"unsupported version " + std::to_string(version) + " (this build reads " +
			std::to_string(kFileVersion) + ")");
	const auto space = getLE(in, 12, 4);
	const auto bins = getLE(in, 16, 4);
	if (space > static_cast<std::uint32_t>(ColourSpace::Chroma))
		throw fail("unknown colour space code " + std::to_string(space));
	if (bins < 1 || bins > 256)
		throw fail("impossible bin count " + std::to_string(bins));
	const std::size_t n = bins * bins * bins;
	if (in.size() != kHeaderBytes + 8 * n + 4)
		throw fail(
			"size " + std::to_string(in.size()) + " bytes, expected " +
			std::to_string(kHeaderBytes + 8 * n + 4) + " (truncated?)");
	if (crcOf(in, in.size() - 4) != getLE(in, in.size() - 4, 4))
		throw fail("checksum mismatch (the file is corrupt)");

	ColourHistogram h(static_cast<ColourSpace>(space), static_cast<int>(bins));
	h.total_ = getLE(in, 20, 8);
	std::uint64_t sum = 0;
	for (std::size_t i = 0; i < n; ++i)
		sum += h.counts_[i] = getLE(in, kHeaderBytes + 8 * i, 8);
	if (sum != h.total_) throw fail("bin counts do not add up to the total");
	return h;
}

void ColourHistogram::save(const std::string& path) const
{
	writeFileAtomically(path, serialize());
}

ColourHistogram ColourHistogram::load(const std::string& path)
{
	requireRegularFile(path, "histogram");
	errno = 0;
	std::ifstream f(path, std::ios::binary);
	if (!f) throw std::runtime_error("cannot open histogram file '" + path + "' (" + std::strerror(errno) + ")");
	std::ostringstream ss;
	ss << f.rdbuf();
	return deserialize(ss.str(), path);
}

}  // namespace omnirange
