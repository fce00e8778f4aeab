#include "omnirange/train/OCamCalibFile.h"

#include "omnirange/config/OptionsTable.h"

#include <stdexcept>

namespace omnirange
{
OCamCalibFile readOCamCalib(const std::string& path)
{
	// The five value lines, in the toolbox's order; comments and blanks between.
	std::vector<std::pair<int, std::vector<double>>> rows;
	forEachDataLine(path, "OCamCalib file", [&](int n, const std::string& t) { rows.push_back({n, parseDoubles(t)}); });
	const auto fail = [&](std::size_t k, const std::string& what) {
		const std::string where = k < rows.size() ? ":" + std::to_string(rows[k].first) : "";
		throw std::runtime_error(path + where + ": " + what + " (is this OCamCalib's calib_results.txt?)");
	};
	if (rows.size() < 5) fail(rows.size(), "expected 5 value lines, found " + std::to_string(rows.size()));
	const auto polynomial = [&](std::size_t k) {
		const auto& v = rows[k].second;
		if (v.empty() || v[0] != static_cast<int>(v[0]) || v[0] < 1 || v.size() != static_cast<std::size_t>(v[0]) + 1)
			fail(k, "a polynomial line is its length N, then N coefficients");
		return std::vector<double>(v.begin() + 1, v.end());
	};
	OCamCalibFile f;
	f.poly = polynomial(0);
	f.inverse = polynomial(1);
	if (rows[2].second.size() != 2) fail(2, "the centre is two numbers, row and column");
	f.row = rows[2].second[0], f.column = rows[2].second[1];
	if (rows[3].second.size() != 3) fail(3, "the affine terms are three numbers, c d e");
	f.c = rows[3].second[0], f.d = rows[3].second[1], f.e = rows[3].second[2];
	const auto& size = rows[4].second;
	if (size.size() != 2 || size[0] < 1 || size[1] < 1 || size[0] != static_cast<int>(size[0]) ||
		size[1] != static_cast<int>(size[1]))
		fail(4, "the image size is two whole numbers, height and width");
	f.height = static_cast<int>(size[0]), f.width = static_cast<int>(size[1]);
	return f;
}

CameraParams ocamCamera(const OCamCalibFile& f, CameraParams start)
{
	start.mirror_model = MirrorModel::OCamCalib;
	start.ocam_poly = f.poly;
	start.ocam_affine = {f.c, f.d, f.e};
	start.cx = f.column, start.cy = f.row;
	start.image_width = f.width, start.image_height = f.height;
	return start;
}

}  // namespace omnirange
