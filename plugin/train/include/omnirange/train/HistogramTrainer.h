#pragma once
// Training the colour histogram the paper's way (§III-A1, Fig. 1): the
// omnicam image as a bird's-eye view (eqs. (1)-(3)), an image of the floor
// the laser shows free over its 180 degrees, and their fusion; the pixels of
// the fusion are counted. The robot's base is masked.

#include <omnirange/train/BirdsEyeView.h>
#include <omnirange/core/CameraModel.h>
#include <omnirange/core/ColourModel.h>
#include <omnirange/core/ExposureCompensation.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

namespace omnirange
{
/** What a user chooses about training (omnirange-train's options). */
struct TrainingParams
{
	double resolution{0.02};  ///< [m/px] of the bird's-eye view
	double laser_margin{0.10};  ///< [m] kept clear of every laser hit (mixed pixels)
	int bins{ColourHistogram::kDefaultBins};  ///< per colour channel
	ColourSpace space{ColourSpace::RGB};
	/** [m] how far beyond each laser hit (after laser_margin) the obstacle's
	 * colours are counted, for the two-class model; 0: the floor only. */
	double obstacle_band{0.25};
	/** [-] also count every pixel as the camera would see it in light this
	 * much dimmer and brighter (gains 1 - a and 1 + a), so the histogram
	 * covers a change of light it was not trained in; 0: as seen. */
	double light_change{0.0};
	/** Count only the disc around the camera nearer than every laser hit
	 * (less laser_margin), all round: what is floor whatever the image's
	 * orientation, so a first histogram for omnirange-calibrate cannot
	 * learn the orientation it was trained with. */
	bool near_disc_only{false};

	/** The keys of [training] (kTrainingSection): all but resolution and near_disc_only. */
	static const OptionsTable<TrainingParams>& table();
};

/** The three images of paper Fig. 1 for one frame. */
struct TrainingFrame
{
	cv::Mat birds_eye;  ///< (a) BGR, forward up, left on the left
	cv::Mat laser_free;  ///< (b) 8-bit, 255 where the laser shows free floor
	cv::Mat fused;  ///< (c) BGR: the bird's-eye pixels that were counted, black elsewhere
	std::size_t pixels{0};  ///< how many were counted
	std::size_t obstacle_pixels{0};  ///< obstacle pixels counted (beyond the laser's hits)
};

/** The 8-bit image as the camera would see it with `gain` more light (saturating at 255). */
cv::Mat withGain(const cv::Mat& bgr, double gain);

class HistogramTrainer
{
   public:
	/** `camera_pose` and the scans' sensorPose are both on the robot. Pixels
	 * from base_range to view_range [m] are trained on: the robot's base
	 * nearer, the rangefinder's max range farther. */
	HistogramTrainer(const OmniCameraModel& camera, const mrpt::poses::CPose3D& camera_pose, double base_range,
					 double view_range, const TrainingParams& p);

	/** Adds one image with the laser scan taken with it. */
	TrainingFrame add(const cv::Mat& omni_bgr, const mrpt::obs::CObservation2DRangeScan& laser);

	/** Adds what `other` (trained with the same camera and parameters) counted. */
	void merge(const HistogramTrainer& other);

	const ColourHistogram& histogram() const { return hist_; }
	/** The floor's colours, the obstacles', and the reference colour of
	 * the floor just beyond the base (the mean of the frames' medians). */
	ColourModel model() const;

   private:
	/** (b) of Fig. 1, and the obstacle pixels: a band just beyond each hit. */
	cv::Mat laserFreeMask(const mrpt::obs::CObservation2DRangeScan& laser, cv::Mat& obstacle) const;
	/** The disc nearer than every laser hit (TrainingParams::near_disc_only). */
	cv::Mat nearDisc(const mrpt::obs::CObservation2DRangeScan& laser) const;

	mrpt::poses::CPose3D camera_pose_;
	double view_range_;
	TrainingParams p_;
	BirdsEyeView view_;
	ColourHistogram hist_, obstacles_;
	FloorRing ring_;
	std::array<double, 3> ring_sum_{};
	int frames_{0};
	cv::Mat base_mask_;  // 255 outside the base and within view_range
};

}  // namespace omnirange
