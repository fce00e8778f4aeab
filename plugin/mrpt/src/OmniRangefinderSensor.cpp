#include "omnirange/mrpt/OmniRangefinderSensor.h"

#include "omnirange/io/ObservationImage.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/hwdrivers/CCameraSensor.h>
#include <mrpt/obs/CObservationImage.h>

#include <optional>
#include <stdexcept>

namespace omnirange
{
IMPLEMENTS_GENERIC_SENSOR(COmniRangefinderSensor, omnirange)

COmniRangefinderSensor::COmniRangefinderSensor() : mrpt::system::COutputLogger("COmniRangefinderSensor") {}
COmniRangefinderSensor::~COmniRangefinderSensor() = default;

void COmniRangefinderSensor::loadConfig_sensorSpecific(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	// rawlog-grabber runs every section as a sensor, so the embedded camera's
	// keys live in ours, prefixed "camera_"; they become a section of their own.
	std::vector<std::string> keys, allowed{"driver", "process_rate", "max_queue_len", "grab_decimation",
										   "sensorLabel", "histogram_file"};
	cfg.getAllKeys(section, keys);
	mrpt::config::CConfigFileMemory camera_cfg;
	const std::string prefix = "camera_";
	for (const auto& k : keys)
		if (k.rfind(prefix, 0) == 0)
		{
			camera_cfg.write("camera", k.substr(prefix.size()), cfg.read_string(section, k, ""));
			allowed.push_back(k);
		}
	if (!camera_cfg.sectionExists("camera"))
		throw std::invalid_argument("[" + section + "] has no camera_* keys (e.g. camera_grabber_type)");
	params_.loadFromConfig(cfg, section, allowed);
	histogram_file_ = cfg.read_string(section, "histogram_file", "", true);
	camera_ = std::make_unique<mrpt::hwdrivers::CCameraSensor>();
	camera_->loadConfig(camera_cfg, "camera");
}

void COmniRangefinderSensor::initialize()
{
	rangefinder_ = std::make_unique<Rangefinder>(params_, ColourModel::load(histogram_file_));
	if (rangefinder_->compensationMissing())
		MRPT_LOG_WARN_STREAM(histogram_file_ << " records no floor colour from training: exposure compensation is off");
	MRPT_LOG_INFO_STREAM("histogram " << histogram_file_ << ", rangefinder options:\n" << params_.asIni());
	camera_->initialize();
}

void COmniRangefinderSensor::setPathForExternalImages(const std::string& directory)
{
	if (camera_) camera_->setPathForExternalImages(directory);
}

void COmniRangefinderSensor::doProcess()
{
	if (!rangefinder_) throw std::logic_error("COmniRangefinderSensor: doProcess() before initialize()");
	const auto obs = camera_->getNextFrame();
	const auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obs);
	if (!img) return;  // no frame now (or a camera type without a single image)
	const cv::Mat bgr = decodeImage(*img);
	// Keep the image inside the observation: a replayed frame's external file
	// is not beside the rawlog being grabbed.
	img->image = mrpt::img::CImage(bgr, mrpt::img::DEEP_COPY);
	auto scan = rangefinder_->toObservation(rangefinder_->processNext(bgr), img->timestamp);
	MRPT_LOG_DEBUG_STREAM("frame scanned: " << scan->getScanSize() << " rays");
	appendObservations({img, scan});
}

}  // namespace omnirange
