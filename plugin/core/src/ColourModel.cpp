#include "omnirange/core/ColourModel.h"

#include <omnirange/config/Output.h>
#include "omnirange/config/OptionsTable.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace omnirange
{
ColourModel::ColourModel(ColourHistogram floor_histogram, ColourHistogram obstacle_histogram)
	: floor(std::move(floor_histogram)), obstacles(std::move(obstacle_histogram))
{
	if (obstacles.space() != floor.space() || obstacles.binsPerChannel() != floor.binsPerChannel())
		throw std::invalid_argument("the floor and obstacle histograms differ in colour space or bins");
}

namespace
{
constexpr char kReferenceTag[8] = {'O', 'M', 'N', 'I', 'R', 'E', 'F', '1'};
}

void ColourModel::save(const std::string& path) const { writeFileAtomically(path, serialize()); }

std::string ColourModel::serialize() const
{
	std::string bytes = floor.serialize() + (hasObstacles() ? obstacles.serialize() : std::string());
	if (hasReference())
	{
		bytes.append(kReferenceTag, sizeof(kReferenceTag));
		for (double v : reference) bytes.append(reinterpret_cast<const char*>(&v), sizeof v);  // little-endian hosts
	}
	return bytes;
}

ColourModel ColourModel::load(const std::string& path)
{
	// Only regular files: a device or a pipe would be read without end.
	requireRegularFile(path, "histogram");
	errno = 0;
	std::ifstream f(path, std::ios::binary);
	if (!f) throw std::runtime_error("cannot open histogram file '" + path + "' (" + std::strerror(errno) + ")");
	// The header says how big the file can be: two histograms and a reference colour. A larger
	// file (a 5 GB mistake) is refused before it is read into memory.
	std::string head(64, '\0');
	f.read(head.data(), static_cast<std::streamsize>(head.size()));
	head.resize(static_cast<std::size_t>(f.gcount()));
	const std::uintmax_t largest = 2 * ColourHistogram::serializedSize(head, path) + 8 + 3 * sizeof(double);
	if (const std::uintmax_t size = std::filesystem::file_size(path); size > largest)
		throw std::runtime_error("histogram file '" + path + "': " + std::to_string(size) + " bytes, more than the " +
								 std::to_string(largest) + " its header allows");
	f.clear();
	f.seekg(0);
	std::ostringstream ss;
	ss << f.rdbuf();
	const std::string bytes = ss.str();
	std::size_t at = ColourHistogram::serializedSize(bytes, path);
	ColourModel m(ColourHistogram::deserialize(bytes.substr(0, at), path));
	const auto starts = [&](const char* tag) { return bytes.compare(at, 8, tag, 8) == 0; };
	if (at < bytes.size() && starts("OMNIHIST"))
	{
		const std::size_t n = ColourHistogram::serializedSize(bytes.substr(at), path);
		m = ColourModel(std::move(m.floor), ColourHistogram::deserialize(bytes.substr(at, n), path + " (obstacles)"));
		at += n;
	}
	if (at < bytes.size())
	{
		if (!starts(kReferenceTag) || bytes.size() != at + 8 + 3 * sizeof(double))
			throw std::runtime_error("histogram file '" + path + "': unreadable data after the histograms");
		for (int c = 0; c < 3; ++c) std::memcpy(&m.reference[c], bytes.data() + at + 8 + c * sizeof(double), sizeof(double));
	}
	return m;
}

bool ColourModel::trainedOnColour() const
{
	constexpr double kGreySpread = 6.0;  // [levels of 255] a grey floor's mean channels in colour JPEGs differ less
	const auto [lo, hi] = std::minmax_element(reference.begin(), reference.end());
	return hasReference() && *hi - *lo > kGreySpread;
}

}  // namespace omnirange
