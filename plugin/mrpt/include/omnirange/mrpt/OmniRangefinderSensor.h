#pragma once
// The rangefinder as an MRPT sensor: `rawlog-grabber -p libomnirange.so`
// with `driver = COmniRangefinderSensor` grabs omnicam frames through an
// embedded CCameraSensor (any of its grabber types, e.g. a live camera, a
// folder of images or a rawlog to replay) and emits each image followed by
// its range scan.
//
// Example (tests/e2e/test_mrpt_programs.cpp runs one):
//   [OMNIRANGE]
//   driver          = COmniRangefinderSensor
//   process_rate    = 10              ; [Hz]
//   histogram_file  = floor.hist      ; from omnirange-train
//   camera_grabber_type = rawlog      ; any CCameraSensor key, prefixed camera_
//   camera_rawlog_file  = old.rawlog
//   camera_sensorLabel  = OMNICAM
//   ; ...and any key of docs/parameters.md (N, K, threshold, R, h, ...)

#include <omnirange/core/Rangefinder.h>

namespace mrpt::hwdrivers
{
class CCameraSensor;
}
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/system/COutputLogger.h>

#include <memory>

namespace omnirange
{
/** Logs through COutputLogger (CGenericSensor has no logger of its own):
 * the options once at INFO, each frame at DEBUG. */
class COmniRangefinderSensor : public mrpt::hwdrivers::CGenericSensor, public mrpt::system::COutputLogger
{
	DEFINE_GENERIC_SENSOR(COmniRangefinderSensor)

   public:
	COmniRangefinderSensor();
	~COmniRangefinderSensor() override;

	void initialize() override;
	void doProcess() override;
	void setPathForExternalImages(const std::string& directory) override;

   protected:
	void loadConfig_sensorSpecific(
		const mrpt::config::CConfigFileBase& cfg, const std::string& section) override;

   private:
	RangefinderParams params_;
	std::string histogram_file_;
	std::unique_ptr<Rangefinder> rangefinder_;
	std::unique_ptr<mrpt::hwdrivers::CCameraSensor> camera_;
};

}  // namespace omnirange
