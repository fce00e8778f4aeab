#pragma once
// Renders what the robot's omnicam sees: for each pixel, the ray through the
// paraboloid's single viewpoint is traced into the world of vertical prisms;
// textured materials, sun and ambient light, floor shadows, the robot's own
// body, the mirror's rim, anti-aliased edges, sensor noise.

#include <omnirange_sim/Materials.h>
#include <omnirange_sim/RobotParams.h>
#include <omnirange_sim/Route.h>
#include <omnirange_sim/World.h>

#include <omnirange/core/CameraModel.h>

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace omnirange::sim
{
class OmniRenderer
{
   public:
	OmniRenderer(const World& world, const RobotParams& robot);

	/** The 8-bit BGR image seen from a robot pose; the noise is drawn from
	 * `noise_seed`, so equal inputs give equal images. */
	cv::Mat render(const Pose2& robot, std::uint64_t noise_seed, int frame = 0) const;

	/** The camera model the renderer uses (with the misalignment applied). */
	const OmniCameraModel& trueCamera() const { return cam_; }

	static constexpr int kBearingBins = 4096;

   private:
	struct Sample
	{
		std::array<double, 3> bgr;
		int surface;  // what was hit: floor, sky, robot, a solid's face
	};
	struct PixelRay
	{
		std::int32_t bin;  // bearing bin in the sensor frame, -1 outside the mirror
		float theta;  // [rad] incidence angle
		std::uint8_t kind;  // 0 scene, 1 robot body, 2 rim, 3 outside
	};
	struct Frame;  // per-frame ray casts

	Sample trace(const Frame& f, int bin, double theta) const;
	Sample shadeFloor(const Frame& f, const Vec2& p) const;
	/** The robot's own shadow ([robot] own_shadow): its sun shadow on this frame's floor. */
	void castOwnShadow(Frame& f) const;
	/** How lit `p` is under the robot's own sun shadow (1: lit, 0: in it); multiplies
	 * `occluded` by the darkening at the body's foot. */
	double ownShadow(const Frame& f, const Vec2& p, double& occluded) const;
	Sample shadeRobot(double theta, double bearing) const;
	PixelRay pixelRay(double u, double v) const;
	/** The frame's ray casts from the robot's pose: its own shadow and the world by bearing. */
	void castFrame(const Pose2& robot, Frame& f) const;
	/** What the ray `pr` through image point (u, v) sees. */
	Sample shade(const Frame& f, const PixelRay& pr, double u, double v) const;
	/** One ray per pixel centre into `img`; each pixel's surface into `surf`. */
	void shadePixels(const Frame& f, cv::Mat& img, cv::Mat& surf) const;
	/** Where a pixel's surface differs from a neighbour's, four rays through its quarters averaged. */
	void antialias(const Frame& f, cv::Mat& img, const cv::Mat& surf) const;
	/** Sensor noise, from the precomputed table at an offset `seed` picks. */
	void addNoise(cv::Mat& img, std::uint64_t seed) const;
	int binOf(double bearing) const;
	void buildShadowMap();
	double floorLight(const Frame& f, const Vec2& p) const;
	/** The occlusion map: 1 in the open, 1 - occlusion at a solid's foot. */
	void buildOcclusionMap();

	const World& world_;
	RobotParams robot_;
	OmniCameraModel cam_;
	NoiseTexture tex_;
	double rim_rho_;
	int robot_material_;  // the body's material, looked up once
	std::vector<PixelRay> rays_;  // per pixel, row-major
	std::vector<float> noise_;  // standard normal values, a power of two long
	cv::Mat shadow_;  // 8-bit floor light map: 255 lit, 0 in shadow
	cv::Mat occlusion_;  // CV_32F, same grid: the floor's light factor near the foot of solids
	Vec2 shadow_lo_;
	double shadow_res_{0.04};
	Vec2 sun_h_;  // horizontal unit vector towards the sun
};

}  // namespace omnirange::sim
