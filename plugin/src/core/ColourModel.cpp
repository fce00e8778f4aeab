#include "omnirange/core/ColourModel.h"

#include "omnirange/io/AtomicWrite.h"

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

void ColourModel::save(const std::string& path) const
{
	writeFileAtomically(path, floor.serialize() + (hasObstacles() ? obstacles.serialize() : std::string()));
}

ColourModel ColourModel::load(const std::string& path)
{
	// Only regular files: a device or a pipe would be read without end.
	if (!std::filesystem::is_regular_file(path)) throw std::runtime_error("cannot open histogram file '" + path + "'");
	std::ifstream f(path, std::ios::binary);
	if (!f) throw std::runtime_error("cannot open histogram file '" + path + "'");
	std::ostringstream ss;
	ss << f.rdbuf();
	const std::string bytes = ss.str();
	const std::size_t first = ColourHistogram::serializedSize(bytes, path);
	ColourHistogram floor = ColourHistogram::deserialize(bytes.substr(0, first), path);
	if (first == bytes.size()) return ColourModel(std::move(floor));
	return ColourModel(std::move(floor), ColourHistogram::deserialize(bytes.substr(first), path + " (obstacles)"));
}

}  // namespace omnirange
