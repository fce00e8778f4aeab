#pragma once
// Colour histogram of free-floor pixels (paper §III-A2): n bins per channel,
// trained by counting; P(colour) = c[colour] / T (eq. (4)).

#include <omnirange/core/ColourSpace.h>
#include <omnirange/config/OptionsTable.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cv
{
class Mat;
}

namespace omnirange
{
/** [bins] The sigma a histogram may be smoothed with (the options table's histogram_smoothing). */
inline constexpr Range kSmoothingRange = Range::closed(0, 16);

class ColourHistogram
{
   public:
	static constexpr int kDefaultBins = 13;  ///< the paper's n
	static constexpr std::uint32_t kFileVersion = 1;

	explicit ColourHistogram(
		ColourSpace space = ColourSpace::RGB, int bins = kDefaultBins);

	const ColourBinner& binner() const { return binner_; }
	ColourSpace space() const { return binner_.space(); }
	int binsPerChannel() const { return binner_.binsPerChannel(); }

	/** Counts one pixel stored as B, G, R bytes. */
	void addPixel(const std::uint8_t* bgr) { ++counts_[binner_.binOf(bgr)], ++total_; }
	/** Counts every pixel of an 8-bit BGR image whose 8-bit mask is non-zero. */
	void addImage(const cv::Mat& bgr, const cv::Mat& mask);
	/** Adds another histogram's counts (same space and bins). */
	void merge(const ColourHistogram& other);

	std::uint64_t count(std::uint32_t bin) const { return counts_.at(bin); }
	std::uint64_t total() const { return total_; }
	bool empty() const { return total_ == 0; }
	/** eq. (4): c[bin] / T; 0 for an empty histogram. */
	double probability(std::uint32_t bin) const;
	/** Every bin's probability after a Gaussian of `sigma` bins along each
	 * of the three channels (what spills past the first or last bin is
	 * dropped); sigma 0: probability() itself. */
	std::vector<double> smoothedProbabilities(double sigma) const;

	/** Saves to a versioned binary file with a CRC-32, atomically. */
	void save(const std::string& path) const;
	/** Loads a file written by save(); throws std::runtime_error naming the
	 * file if it is missing, truncated, of another version or corrupt. */
	static ColourHistogram load(const std::string& path);

	/** How many bytes the histogram at the start of `bytes` takes (from its
	 * header); throws std::runtime_error naming `what` if that is no histogram. */
	static std::size_t serializedSize(const std::string& bytes, const std::string& what);
	/** The file's bytes (what save() writes) and their inverse. */
	std::string serialize() const;
	static ColourHistogram deserialize(
		const std::string& bytes, const std::string& what);

   private:
	ColourBinner binner_;
	std::vector<std::uint64_t> counts_;
	std::uint64_t total_{0};
};

}  // namespace omnirange
