#pragma once
// Polar scanning (paper §III-B1, Fig. 2): S scanlines from the image centre
// outwards, each searched for the floor's end with the N/K filters, and the
// hit pixel turned into metres with the camera model (eq. (6)).

#include <omnirange/core/BoundaryRefinement.h>
#include <omnirange/core/BrightnessStep.h>
#include <omnirange/core/CameraModel.h>
#include <omnirange/core/EdgeBias.h>
#include <omnirange/core/HitFilter.h>
#include <omnirange/core/PixelClassifier.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cv
{
class Mat;
}

namespace omnirange
{
/** Why a ray has the range it has. */
enum class RayStatus : std::uint8_t
{
	Hit,  ///< the floor ends here: a measured range
	NoHit,  ///< free up to the max-range radius: reports max range
	TooClose,  ///< the floor ends inside min range: reports min range
	Outlier,  ///< rejected by the outlier filter (range kept, not valid)
	/** The free stretch crosses colours the floor rarely shows: free only up
	 * to where they start (range: that confident extent). */
	Unsure
};
std::string toString(RayStatus s);
std::string toString(BoundaryModel m);
/** "midpoint" or "subpixel"; throws std::invalid_argument otherwise. */
BoundaryModel boundaryModelFromString(const std::string& name);

/** One ray of a scan. */
struct Ray
{
	double bearing{0};  ///< [rad] in the sensor frame
	float range{0};  ///< [m] measured, or min/max range by status
	RayStatus status{RayStatus::NoHit};
	float hit_rho{-1};  ///< [px] image radius of the boundary, -1 if none
	/** What the N/K search found on this ray's scanline, and why (its pixel
	 * indices count from the scanline's first pixel, at base_radius). */
	HitSearch search{};
	/** The brightness step (BrightnessStep.h), not the colour, ended this ray. */
	bool by_step{false};
	/** Pixels at the base passed as the robot's own shadow (base_shadow); the
	 * search's indices still count from the scanline's first pixel. */
	int past_base{0};
	/** The hit pixel's contrast with the floor before it (EdgeBias.h); NaN
	 * without a hit or too near the base to tell. */
	float edge_contrast{std::numeric_limits<float>::quiet_NaN()};
	/** Where the sure floor ends before the ray's end (sure_run doubtful
	 * pixels start there), as a pixel index and a range [m]; -1 when the
	 * evidence carries the whole free stretch. */
	int sure_end{-1};
	float sure_range{0};
	/** [0, 1] the share of the range the ray claims free that sure floor
	 * supports: 1 for a hit or free ray, below 1 for an unsure one. */
	float confidence{1};
};

/** Bearing [rad] of scanline i of S: MRPT's angle of ray i in a scan of S
 * rays over the aperture 2 pi (S-1)/S, i.e. -pi (S-1)/S + 2 pi i / S. */
double scanlineBearing(int i, int S);

/** The aperture [rad] of a scan of S rays spaced 2 pi / S. */
double scanAperture(int S);

struct PolarScannerParams
{
	int scanlines{360};  ///< S
	double base_radius{40.0};  ///< [px] the robot base; scanlines start here
	double min_range{0.40};  ///< [m]
	double max_range{3.8};  ///< [m]
	/** [px] where the floor's end is put, outwards from the midpoint between
	 * the last free and the first non-free pixel (default 0: exact for hard
	 * edges; blurred edges want about +0.5, see omnirange-calibrate). */
	double boundary_offset{0.0};
	/** How the edge is placed between pixels (BoundaryRefinement.h). */
	BoundaryModel boundary_model{BoundaryModel::Subpixel};
	/** [px] how far past the first non-free pixel the sub-pixel model may
	 * place the edge (1: the limit before commit e13c8b5;
	 * docs/results.md measures both). */
	double boundary_reach{kMaxBoundaryReach};
	HitFilterParams filter{};
	/** [-] a brightness step of at least this (natural log of the ratio of
	 * window means) before the colour's hit ends the ray there; 0: off. */
	double step_threshold{0.0};
	int step_window{4};  ///< [px] pixels averaged on each side of a step
	StepSign step_sign{StepSign::Either};  ///< which steps end a ray (BrightnessStep.h)
	/** [m] a non-free run from the scanline's first pixel that ends within this
	 * distance of it, with N free pixels behind it (runs of at most K non-free
	 * negated), is taken for the robot's own
	 * shadow (or body) and passed; 0: such a ray is too close (the paper's). */
	double base_shadow{1.0};
	/** [m] per contrast bin (EdgeBias.h), added to a hit's range: the width
	 * of the darkened floor before an obstacle's foot, learned against the
	 * laser by omnirange-train --learn; empty: none (the paper's). */
	std::vector<double> edge_bias{};
	/** [px] doubtful pixels (colours the floor rarely shows, sure_floor_share)
	 * in a row, runs of at most K sure ones negated, that end the stretch a
	 * ray may claim free; 0: no doubt, every ray hit or free (the paper's). */
	int sure_run{20};

	static const OptionsTable<PolarScannerParams>& table();
	/** Throws std::invalid_argument naming the key; the camera bounds the radii. */
	void validate(const OmniCameraModel& camera) const;
};

class PolarScanner
{
   public:
	/** Precomputes each scanline's pixels. Throws std::invalid_argument if a
	 * parameter is impossible or the scan circle (max range plus the N+K
	 * window) does not fit in the camera's image. */
	PolarScanner(const OmniCameraModel& camera, const PolarScannerParams& p);

	const PolarScannerParams& params() const { return p_; }
	/** Image radius [px] of the max range. */
	double maxRangeRho() const { return max_rho_; }
	/** Largest image radius [px] any scanline reads. */
	double scanRadius() const { return scan_radius_; }

	/** Throws std::invalid_argument unless `bgr` is 8-bit BGR of the camera's size. */
	void checkImage(const cv::Mat& bgr) const;
	/** Scans one BGR image of the camera's size. */
	std::vector<Ray> scan(const cv::Mat& bgr, const PixelClassifier& classifier) const;

	/** The box of the image the scanlines read (every stage of a ray reads only its scanline's pixels). */
	PixelBox pixelsRead() const;
	/** Pixel indices (row * width + col) of scanline s, innermost first. */
	std::vector<std::int32_t> scanlinePixels(int s) const;

   private:
	struct Scanline
	{
		double bearing;
		std::size_t first;  // into pixel_/mid_range_
		int count;  // pixels on this scanline
		int last_candidate;  // last pixel whose range is within max range
		int first_in_range;  // first pixel whose range is at least min range
	};

	/** Image radius [px] at fractional pixel index k of a scanline. */
	double rhoAt(const Scanline& line, double k) const;
	/** Where the floor resumes past a non-free run at the base, within
	 * base_shadow of the first pixel (N pixels free but for runs of at most K
	 * non-free: the N/K filter with the classes swapped); 0 if it does not. */
	template <class IsFree>
	int floorPastBase(const Scanline& line, IsFree& is_free) const;
	/** The paper's search (N/K filter) on the colour's classes, passing a
	 * shadow at the base (base_shadow): fills ray.search and ray.past_base. */
	template <class IsFree>
	void searchColour(const Scanline& line, IsFree& is_free, Ray& ray) const;
	/** The pixel that ends the ray: the colour's hit, or a brightness step
	 * before it (BrightnessStep.h); -1 for none. Sets ray.by_step. */
	int endOfFloor(const Scanline& line, const std::uint8_t* bgr, const std::int32_t* pix, Ray& ray) const;
	/** The ray's range, status and contrast from the pixel `hit` that ends it:
	 * the boundary model, the edge bias, too close. */
	void placeHit(const Scanline& line, const std::uint8_t* bgr, const std::int32_t* pix, int hit, Ray& ray) const;
	/** Where sure floor ends before pixel `end`, the ray's claimed end,
	 * from the scanline's classes (kNotFree, kFree, kDoubtfulFree) up to
	 * there: fills ray.sure_end and ray.sure_range. */
	void findDoubt(const Scanline& line, const std::uint8_t* classes, int end, Ray& ray) const;

	PolarScannerParams p_;
	int width_, height_;
	double max_rho_{0}, scan_radius_{0};
	int longest_line_{0};  // pixels on the longest scanline
	std::vector<Scanline> lines_;
	std::vector<std::int32_t> pixel_;  // row * width + col
	// Range [m] reported for a hit at this pixel: the floor distance of the
	// midpoint between it and the pixel before it (the boundary lies there).
	std::vector<float> mid_range_;
	std::vector<float> mid_rho_;  // [px] that midpoint's image radius
	std::vector<float> rho_;  // [px] each pixel's own image radius
	OmniCameraModel camera_;
};

}  // namespace omnirange
