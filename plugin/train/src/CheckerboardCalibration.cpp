#include "omnirange/train/CheckerboardCalibration.h"
#include "omnirange/io/ObservationImage.h"
#include "omnirange/config/OptionsTable.h"
#include "omnirange/config/Activity.h"

#include <mrpt/img/CImage.h>
#include <mrpt/vision/chessboard_find_corners.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/ccalib/omnidir.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace omnirange
{
bool findCheckerboardCorners(const cv::Mat& gray, const cv::Size& pattern, const std::string& detector,
							 std::vector<cv::Point2f>& corners)
{
	if (detector == "classic")
	{
		if (!cv::findChessboardCorners(gray, pattern, corners, cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE))
			return false;
		cv::cornerSubPix(gray, corners, cv::Size(5, 5), cv::Size(-1, -1),
						 cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 30, 0.01));
		return true;
	}
	if (detector == "sector-based")
		return cv::findChessboardCornersSB(gray, pattern, corners, cv::CALIB_CB_EXHAUSTIVE | cv::CALIB_CB_ACCURACY);
	if (detector == "mrpt-scaramuzza")
	{
		std::vector<mrpt::img::TPixelCoordf> found;
		const mrpt::img::CImage image(gray, mrpt::img::DEEP_COPY);
		if (!mrpt::vision::findChessboardCorners(image, found, pattern.width, pattern.height, true, true)) return false;
		corners.clear();
		for (const auto& p : found) corners.emplace_back(p.x, p.y);
		return corners.size() == static_cast<std::size_t>(pattern.area());
	}
	throw std::invalid_argument("unknown corner detector '" + detector +
								"' (classic, sector-based or mrpt-scaramuzza)");
}

namespace
{
/** [share of the way to the next corners] Where the four squares around a corner are sampled: well inside each. */
constexpr float kSaddleReach = 0.35f;
/** [share of a square's side] The side of the patch averaged at each sample. */
constexpr double kSaddlePatch = 0.2;

/** Whether `grid` holds a corner for every place of `pattern`, with neighbours to sample from. */
bool isGridOf(const cv::Size& pattern, const std::vector<cv::Point2f>& grid)
{
	return pattern.width >= 2 && pattern.height >= 2 && grid.size() == static_cast<std::size_t>(pattern.area());
}

struct Saddle
{
	double contrast;  ///< [grey levels] between the two diagonal pairs of squares
	double mismatch;  ///< [grey levels] the larger difference within a pair
};

/** The four squares around corner (r, c) of `grid`, along the directions to its neighbours in the grid. */
Saddle saddleAt(const cv::Mat& gray, const cv::Size& pattern, const std::vector<cv::Point2f>& grid, int r, int c)
{
	const auto at = [&](int row, int col) { return grid[static_cast<std::size_t>(row * pattern.width + col)]; };
	const cv::Point2f p = at(r, c);
	// Towards the next corner along the row and down the column (from the one before at the grid's end).
	const cv::Point2f du = c + 1 < pattern.width ? at(r, c + 1) - p : p - at(r, c - 1);
	const cv::Point2f dv = r + 1 < pattern.height ? at(r + 1, c) - p : p - at(r - 1, c);
	const double side = std::min(cv::norm(du), cv::norm(dv));
	const int patch = std::max(1, static_cast<int>(side * kSaddlePatch)) | 1;
	const auto level = [&](float su, float sv) {
		cv::Mat px;
		cv::getRectSubPix(gray, cv::Size(patch, patch), p + kSaddleReach * (su * du + sv * dv), px, CV_32F);
		return cv::mean(px)[0];
	};
	const double pp = level(1, 1), mm = level(-1, -1), pm = level(1, -1), mp = level(-1, 1);
	return {std::abs((pp + mm) - (pm + mp)) / 2, std::max(std::abs(pp - mm), std::abs(pm - mp))};
}
}  // namespace

double saddleContrast(const cv::Mat& gray, const cv::Size& pattern, const std::vector<cv::Point2f>& grid)
{
	if (!isGridOf(pattern, grid)) return 0;
	std::vector<double> contrast;
	for (int r = 0; r < pattern.height; ++r)
		for (int c = 0; c < pattern.width; ++c) contrast.push_back(saddleAt(gray, pattern, grid, r, c).contrast);
	const auto middle = contrast.begin() + static_cast<std::ptrdiff_t>(contrast.size() / 2);
	std::nth_element(contrast.begin(), middle, contrast.end());
	return *middle;
}

bool isCheckerboardGrid(const cv::Mat& gray, const cv::Size& pattern, const std::vector<cv::Point2f>& grid,
						double contrast)
{
	if (!isGridOf(pattern, grid)) return false;
	for (int r = 0; r < pattern.height; ++r)
		for (int c = 0; c < pattern.width; ++c)
		{
			const Saddle s = saddleAt(gray, pattern, grid, r, c);
			if (s.contrast < kSaddleContrastShare * contrast || s.mismatch > kSaddleMismatchShare * s.contrast)
				return false;
		}
	return true;
}

int CheckerboardCalibration::found() const
{
	return static_cast<int>(std::count_if(images.begin(), images.end(), [](const auto& i) { return i.found; }));
}

int CheckerboardCalibration::used() const
{
	return static_cast<int>(std::count_if(images.begin(), images.end(), [](const auto& i) { return i.used; }));
}

CameraParams meiCamera(const CheckerboardCalibration& c, CameraParams start)
{
	start.mirror_model = MirrorModel::Mei;
	start.xi = c.xi;
	start.gamma = c.K(0, 0);
	start.aspect = c.K(1, 1) / c.K(0, 0);
	start.skew = c.K(0, 1);
	start.k1 = c.D[0], start.k2 = c.D[1];
	start.p1 = c.D[2], start.p2 = c.D[3];
	start.cx = c.K(0, 2), start.cy = c.K(1, 2);
	start.image_width = c.image_size.width, start.image_height = c.image_size.height;
	return start;
}

std::string CheckerboardCalibration::yaml() const
{
	cv::FileStorage fs(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
	fs << "image_width" << image_size.width << "image_height" << image_size.height;
	fs << "camera_matrix" << cv::Mat(K) << "xi" << xi << "distortion" << cv::Mat(D) << "rms_px" << rms;
	fs << "images_found" << found() << "images_used" << used();
	return fs.releaseAndGetString();
}

namespace
{
using Boards3d = std::vector<std::vector<cv::Vec3d>>;
using Boards2d = std::vector<std::vector<cv::Vec2d>>;

/** The principal point's spread over calibrations that each leave out one
 * group of the `used` boards (the groups: every k-th, so each run keeps
 * boards from all over the sequence). Sets c.centre_spread and c.centre_subsets. */
void measureCentreSpread(const Boards3d& object, const Boards2d& image, const std::vector<int>& used,
						 const cv::TermCriteria& stop, CheckerboardCalibration& c)
{
	const int n = static_cast<int>(used.size());
	if (n < 4) return;  // leaving one out must leave the 3 a calibration needs
	const int groups = std::min(n, kCentreSubsets);
	for (int g = 0; g < groups; ++g)
	{
		activity::set("calibrating without board group " + std::to_string(g + 1));
		Boards3d o;
		Boards2d i;
		for (int k = 0; k < n; ++k)
			if (k % groups != g) o.push_back(object[used[k]]), i.push_back(image[used[k]]);
		cv::Mat K, D, xi, idx;
		std::vector<cv::Mat> rvecs, tvecs;
		try
		{
			cv::omnidir::calibrate(o, i, c.image_size, K, xi, D, rvecs, tvecs, 0, stop, idx);
		}
		catch (const cv::Exception&)
		{
			continue;  // a subset it cannot start from: no centre to compare
		}
		const double dx = K.at<double>(0, 2) - c.K(0, 2), dy = K.at<double>(1, 2) - c.K(1, 2);
		c.centre_spread = std::max(c.centre_spread, std::hypot(dx, dy));
		++c.centre_subsets;
	}
}
}  // namespace

namespace
{
void requireBoardAndFiles(const std::vector<std::string>& files, const CheckerboardOptions& o)
{
	if (o.columns < 2 || o.rows < 2 || o.columns > kMaxBoardCorners || o.rows > kMaxBoardCorners || !(o.square >= 0.001 && o.square <= 10))
		throw std::invalid_argument("the board needs 2 to " + std::to_string(kMaxBoardCorners) +
									" inner corners each way and a square within [0.001, 10] m");
	// One photograph given twice would count as two boards and look like agreement.
	requireNamedOnce(files, "image");
}

/** The image `file`, checked against the first one's size and the board's. */
cv::Mat readBoardImage(const std::string& file, const CheckerboardOptions& o, cv::Size& first_size)
{
	activity::set("reading image '" + file + "'");
	const cv::Mat gray = decodeImageFile(file, "", cv::IMREAD_GRAYSCALE);
	if (first_size.empty()) first_size = gray.size();
	if (gray.size() != first_size)
		throw std::runtime_error("image '" + file + "' is " + sizeText(gray.size()) + ", the first image " +
								 sizeText(first_size) + ": one of them is not of this camera");
	// Fewer than a few pixels a square cannot show a board (and OpenCV's detectors assert on it).
	if (gray.cols < 4 * (o.columns + 1) || gray.rows < 4 * (o.rows + 1))
		throw std::runtime_error("image '" + file + "' is " + std::to_string(gray.cols) + "x" + std::to_string(gray.rows) +
								 " px: too small to show a board of " + std::to_string(o.columns) + "x" +
								 std::to_string(o.rows) + " inner corners");
	return gray;
}

/** One step past the last of `line` (corners in order along a row or column of the board): quadratic from
 * the last three, as the mirror bends the board's lines, linear from two. */
cv::Point2f onePast(const std::vector<cv::Point2f>& line)
{
	const std::size_t n = line.size();
	return n >= 3 ? 3.f * line[n - 1] - 3.f * line[n - 2] + line[n - 3] : 2.f * line[n - 1] - line[n - 2];
}

/** `grid` (`pattern`) with one column more on its right and left, one row more below and above, each new
 * corner where its row or column of the board leads: where a miscounted board's missing corners lie. */
std::vector<std::pair<cv::Size, std::vector<cv::Point2f>>> gridsOneLarger(const cv::Size& pattern,
																		   const std::vector<cv::Point2f>& grid)
{
	const int w = pattern.width, h = pattern.height;
	const auto at = [&](int c, int r) { return grid[static_cast<std::size_t>(r * w + c)]; };
	const auto line = [&](int from_c, int from_r, int dc, int dr, int n) {
		std::vector<cv::Point2f> l;
		for (int k = 0; k < n; ++k) l.push_back(at(from_c + k * dc, from_r + k * dr));
		return onePast(l);
	};
	std::vector<cv::Point2f> right, left, below = grid, above;
	for (int r = 0; r < h; ++r)
	{
		left.push_back(line(w - 1, r, -1, 0, w));
		for (int c = 0; c < w; ++c) left.push_back(at(c, r)), right.push_back(at(c, r));
		right.push_back(line(0, r, 1, 0, w));
	}
	for (int c = 0; c < w; ++c) below.push_back(line(c, 0, 0, 1, h)), above.push_back(line(c, h - 1, 0, -1, h));
	above.insert(above.end(), grid.begin(), grid.end());
	return {{{w + 1, h}, right}, {{w + 1, h}, left}, {{w, h + 1}, below}, {{w, h + 1}, above}};
}

/** The board's corners in `gray` by the first detector that finds them, and
 * whether a column or row more of checkerboard corners lies past one of its
 * edges (a miscounted board). */
CheckerboardImage detectBoard(const cv::Mat& gray, const CheckerboardOptions& o, std::vector<cv::Point2f>& corners)
{
	const cv::Size pattern(o.columns, o.rows);
	CheckerboardImage info;
	for (const std::string& detector : o.detectors)
		if (findCheckerboardCorners(gray, pattern, detector, corners))
		{
			info.found = true, info.detector = detector;
			// A miscount means the real grid has more inner corners, each one a corner of four squares,
			// where the board's rows or columns lead on; past a board's edge, on a white margin, there is none.
			// A line that leaves the image is not seen, and tells nothing.
			const double contrast = saddleContrast(gray, pattern, corners);
			const cv::Rect2f image(0, 0, static_cast<float>(gray.cols), static_cast<float>(gray.rows));
			const auto seen = [&](const cv::Point2f& p) { return image.contains(p); };
			for (const auto& [size, larger] : gridsOneLarger(pattern, corners))
				info.part_of_larger = info.part_of_larger || (std::all_of(larger.begin(), larger.end(), seen) &&
															  isCheckerboardGrid(gray, size, larger, contrast));
			break;
		}
	return info;
}

/** The first of `boards` whose corners lie within kSameViewPx of `corners` on average, or -1. */
int sameView(const std::vector<cv::Point2f>& corners, const std::vector<std::vector<cv::Vec2d>>& boards)
{
	for (std::size_t b = 0; b < boards.size(); ++b)
	{
		double sum = 0;
		for (std::size_t i = 0; i < corners.size(); ++i) sum += cv::norm(cv::Vec2d(corners[i].x, corners[i].y) - boards[b][i]);
		if (sum < kSameViewPx * static_cast<double>(corners.size())) return static_cast<int>(b);
	}
	return -1;
}

/** cv::omnidir's fit of the boards found; each kept board's own reprojection error into its image. */
void fitModel(const std::vector<std::vector<cv::Vec3d>>& object, const std::vector<std::vector<cv::Vec2d>>& image,
			  const std::vector<std::size_t>& which, const CheckerboardOptions& o, CheckerboardCalibration& out)
{
	cv::Mat K, D, xi, idx;
	std::vector<cv::Mat> rvecs, tvecs;
	const cv::TermCriteria stop(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, o.max_iterations, 1e-8);
	out.rms = cv::omnidir::calibrate(object, image, out.image_size, K, xi, D, rvecs, tvecs, 0, stop, idx);
	out.K = cv::Matx33d(K);
	out.xi = xi.at<double>(0);
	out.D = cv::Vec4d(D);
	for (int k = 0; k < static_cast<int>(idx.total()); ++k)  // idx indexes `object`
	{
		const int b = idx.at<int>(k);
		std::vector<cv::Vec2d> projected;
		cv::omnidir::projectPoints(object[b], projected, rvecs[k], tvecs[k], K, out.xi, D);
		double sum = 0;
		for (std::size_t i = 0; i < projected.size(); ++i)
		{
			const cv::Vec2d d = projected[i] - image[b][i];
			sum += d.dot(d);
		}
		auto& info = out.images[which[b]];
		info.used = true;
		info.rms = std::sqrt(sum / static_cast<double>(projected.size()));
	}
	measureCentreSpread(object, image, std::vector<int>(idx.begin<int>(), idx.end<int>()), stop, out);
}
}  // namespace

CheckerboardCalibration calibrateFromCheckerboards(const std::vector<std::string>& files, const CheckerboardOptions& o)
{
	requireBoardAndFiles(files, o);
	std::vector<cv::Vec3d> board;
	for (int r = 0; r < o.rows; ++r)
		for (int c = 0; c < o.columns; ++c) board.push_back({c * o.square, r * o.square, 0.0});

	CheckerboardCalibration out;
	std::vector<std::vector<cv::Vec3d>> object;
	std::vector<std::vector<cv::Vec2d>> image;
	std::vector<std::size_t> which;  // index in out.images of each board
	for (const auto& file : files)
	{
		const cv::Mat gray = readBoardImage(file, o, out.image_size);
		std::vector<cv::Point2f> corners;
		// A miscount is checked on every board: one that shows its whole grid is enough to tell, and any may be it.
		CheckerboardImage info = detectBoard(gray, o, corners);
		info.file = file;
		if (info.found)
			if (const int same = sameView(corners, image); same >= 0) info.same_view_as = out.images[which[same]].file;
		if (info.found && info.same_view_as.empty())
		{
			object.push_back(board);
			std::vector<cv::Vec2d> points;
			for (const auto& p : corners) points.push_back({p.x, p.y});
			image.push_back(points);
			which.push_back(out.images.size());
		}
		out.images.push_back(info);
	}
	if (object.size() < 3)
		throw std::runtime_error("the board was found in " + std::to_string(object.size()) + " of " +
								 std::to_string(files.size()) + " images (views of the same board position counted once); "
								 "calibration needs at least 3");
	fitModel(object, image, which, o, out);
	return out;
}

}  // namespace omnirange
