#pragma once
// The camera's intrinsics from checkerboard images, in Mei's unified model
// (OpenCV contrib's cv::omnidir: focal lengths, skew, principal point, xi and
// radial/tangential distortion): what a user with a hyperbolic, parabolic or
// fisheye-like omnicam and a printed board can measure before anything else.
// Corners come from OpenCV's classic detector (sub-pixel refined); where it
// fails (strongly curved boards near the mirror's rim), from its sector-based
// detector; where both fail, from MRPT's OCamCalib-based one.

#include <omnirange/core/CameraModel.h>

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace omnirange
{
/** The most inner corners a board may have along each side. */
inline constexpr int kMaxBoardCorners = 100;

struct CheckerboardOptions
{
	int columns{8}, rows{6};  ///< inner corners
	double square{0.042};  ///< [m] side of a square
	int max_iterations{300};
	/** Corner detectors, tried in this order until one finds the board:
	 * "classic" (OpenCV's, sub-pixel refined), "sector-based" (OpenCV's
	 * findChessboardCornersSB), "mrpt-scaramuzza" (MRPT's OCamCalib-based
	 * detector, mrpt::vision::findChessboardCorners). */
	std::vector<std::string> detectors{"classic", "sector-based", "mrpt-scaramuzza"};
};

struct CheckerboardImage
{
	std::string file;
	bool found{false};
	std::string detector;  ///< which of CheckerboardOptions::detectors found it
	bool used{false};  ///< kept by the calibration (cv::omnidir drops some it cannot initialise)
	double rms{0};  ///< [px] this image's reprojection error, when used
	/** Past one of the board's edges, where its rows or columns lead on, lies
	 * one more column or row of checkerboard corners (isCheckerboardGrid): the
	 * board given is likely miscounted (a part of the real one, its corners
	 * then matched to the wrong squares). Checked on every board found. Past
	 * a board's outer edge, where a white margin begins, there is no corner. */
	bool part_of_larger{false};
	/** The board lies where it lay in this earlier image (its corners within
	 * kSameViewPx on average): a copy or a still camera's burst adds no view,
	 * and would make a fit of one view look pinned down. Not used. */
	std::string same_view_as;
};

/** [px] A board whose corners lie within this of an earlier one's, on average, is the same view. */
inline constexpr double kSameViewPx = 2.0;

/** At most this many calibrations again, each without one group of boards, for the centre's spread. */
inline constexpr int kCentreSubsets = 8;

struct CheckerboardCalibration
{
	std::vector<CheckerboardImage> images;
	cv::Size image_size;
	cv::Matx33d K;  ///< fx, skew, cx / fy, cy
	double xi{0};
	cv::Vec4d D;  ///< k1, k2, p1, p2
	double rms{0};  ///< [px] over the used images
	/** [px] How far the principal point moves when the calibration is run
	 * again without one used board (or one group of them, at most
	 * kCentreSubsets runs): the farthest such centre from the whole set's.
	 * A small RMS with a large spread is a centre the boards do not pin down. */
	double centre_spread{0};
	int centre_subsets{0};  ///< how many such runs converged (0: fewer than 4 boards used, not measured)
	int found() const;
	int used() const;
	/** The result as OpenCV's YAML (the keys cv::omnidir users expect: camera_matrix, xi, distortion). */
	std::string yaml() const;
};

/** Of the four squares around a true inner corner, the two on one diagonal
 * differ from each other by at most this share of the difference between
 * the diagonals. (On a board's outer edge, with white margin on both outer
 * sides, they differ by twice that difference.) */
inline constexpr double kSaddleMismatchShare = 0.5;
/** A true inner corner's diagonals differ by at least this share of the
 * board's own (saddleContrast). */
inline constexpr double kSaddleContrastShare = 0.3;

/** [grey levels] The median over `grid`'s corners (`pattern`: columns x rows,
 * row by row, as findCheckerboardCorners gives them) of the difference
 * between the two diagonal pairs of squares around each corner in `gray`:
 * how far the board's dark and light squares differ there. */
double saddleContrast(const cv::Mat& gray, const cv::Size& pattern, const std::vector<cv::Point2f>& grid);

/** Whether every corner of `grid` is a checkerboard's inner corner in `gray`:
 * of the four squares around it (sampled from its neighbours in the grid),
 * the diagonal ones alike (kSaddleMismatchShare) and the diagonals apart by
 * at least kSaddleContrastShare of `contrast` (saddleContrast of the board
 * found). A miscounted board's larger grid passes, each of its corners a
 * real one; a row on the board's edge, margin on its outer side, does not. */
bool isCheckerboardGrid(const cv::Mat& gray, const cv::Size& pattern, const std::vector<cv::Point2f>& grid,
						double contrast);

/** A board's inner corners (`pattern`: columns x rows) in an 8-bit grey
 * image by one of CheckerboardOptions::detectors, row by row; false when that
 * detector does not find them. Throws std::invalid_argument on an unknown one. */
bool findCheckerboardCorners(const cv::Mat& gray, const cv::Size& pattern, const std::string& detector,
							 std::vector<cv::Point2f>& corners);

/** The rangefinder's camera from a calibration: mirror_model = mei with all
 * of it (xi, gamma = fx, aspect = fy / fx, skew, k1, k2, p1, p2, the
 * principal point as cx, cy, the image size); the rest of `start` (h,
 * orientation) is kept. */
CameraParams meiCamera(const CheckerboardCalibration& c, CameraParams start = {});

/** Throws std::runtime_error naming the file if an image cannot be read or
 * has another size than the first, and if fewer than 3 boards are found. */
CheckerboardCalibration calibrateFromCheckerboards(const std::vector<std::string>& files,
												   const CheckerboardOptions& options = {});

}  // namespace omnirange
