#pragma once
// Checkerboards drawn through a hyperbolic mirror, in Mei's unified model
// (cv::omnidir's, without distortion): each pixel's ray, lifted onto the
// unit sphere, meets the board's plane (dark squares, white margin) or the
// grey room behind it; past the mirror's rim the image is black. Four
// samples a pixel, then a slight blur, as a lens would.

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace omnirange::test
{
struct RenderedBoard
{
	cv::Size squares{9, 7};  ///< squares across and down: 8 x 6 inner corners
	double square{0.04};  ///< [m]
	double margin{0.04};  ///< [m] white paper round the squares
	/** [m] Where inner corner (c, r) lies on the board: (c, r) * square. */
	cv::Point3d corner(int c, int r) const { return {c * square, r * square, 0}; }
};

struct MirrorCamera
{
	cv::Size image{800, 800};
	double f{260}, cx{400}, cy{400};  ///< [px]
	double xi{0.9};  ///< within (0, 1): a hyperboloid
	double rim{390};  ///< [px] the mirror's edge, from the centre
};

/** The board in the camera's frame: X_camera = R X_board + t. */
struct BoardPose
{
	cv::Matx33d R;
	cv::Vec3d t;
};

/** The ray of pixel (u, v) on the unit sphere (Mei's lifting). */
inline cv::Vec3d mirrorRay(const MirrorCamera& c, double u, double v)
{
	const double mx = (u - c.cx) / c.f, my = (v - c.cy) / c.f, r2 = mx * mx + my * my;
	const double l = (c.xi + std::sqrt(1 + (1 - c.xi * c.xi) * r2)) / (1 + r2);
	return {l * mx, l * my, l - c.xi};
}

/** The board's middle `distance` [m] away at `azimuth` and `elevation` [rad]
 * about the mirror's axis (the camera's z), facing the camera, then tilted
 * by `tilt` about its rows and turned by `roll` about its normal [rad]. */
inline BoardPose facingPose(const RenderedBoard& b, double azimuth, double elevation, double distance, double tilt,
							double roll)
{
	const cv::Vec3d z(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
	const cv::Vec3d x = cv::normalize(cv::Vec3d(0, 0, 1).cross(z));
	const cv::Vec3d y = z.cross(x);
	const cv::Matx33d facing(x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]);
	const double ct = std::cos(tilt), st = std::sin(tilt), cr = std::cos(roll), sr = std::sin(roll);
	const cv::Matx33d tilted(1, 0, 0, 0, ct, -st, 0, st, ct), turned(cr, -sr, 0, sr, cr, 0, 0, 0, 1);
	BoardPose p;
	p.R = facing * tilted * turned;
	const cv::Point3d m = b.corner(b.squares.width - 2, b.squares.height - 2) * 0.5;  // the inner corners' middle
	p.t = distance * z - p.R * cv::Vec3d(m.x, m.y, m.z);
	return p;
}

/** The 8-bit grey image of board `b` at `pose` through mirror camera `c`. */
inline cv::Mat renderBoard(const MirrorCamera& c, const RenderedBoard& b, const BoardPose& pose)
{
	constexpr double kInk = 25, kPaper = 235, kRoom = 110, kOutside = 0;  // grey levels
	const cv::Vec3d n(pose.R(0, 2), pose.R(1, 2), pose.R(2, 2));
	const double nt = n.dot(pose.t);
	const cv::Matx33d to_board = pose.R.t();
	const double margin = b.margin / b.square;  // [squares]
	const auto level = [&](double u, double v) {
		const cv::Vec3d d = mirrorRay(c, u, v);
		const double dn = n.dot(d);
		if (std::abs(dn) < 1e-12 || nt / dn <= 0) return kRoom;
		const cv::Vec3d local = to_board * (d * (nt / dn) - pose.t);
		// in squares from the first square's outer edge: inner corner (c, r) at (c + 1, r + 1)
		const double x = local[0] / b.square + 1, y = local[1] / b.square + 1;
		if (x < -margin || y < -margin || x >= b.squares.width + margin || y >= b.squares.height + margin) return kRoom;
		if (x < 0 || y < 0 || x >= b.squares.width || y >= b.squares.height) return kPaper;
		return (static_cast<int>(x) + static_cast<int>(y)) % 2 == 0 ? kInk : kPaper;
	};
	cv::Mat_<uchar> img(c.image, static_cast<uchar>(kOutside));
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
		{
			if (std::hypot(u - c.cx, v - c.cy) > c.rim) continue;
			double sum = 0;
			for (int k = 0; k < 4; ++k) sum += level(u - 0.25 + 0.5 * (k % 2), v - 0.25 + 0.5 * (k / 2));
			img(v, u) = cv::saturate_cast<uchar>(sum / 4);
		}
	cv::Mat blurred;
	cv::GaussianBlur(img, blurred, cv::Size(3, 3), 0.7);
	return blurred;
}

}  // namespace omnirange::test
