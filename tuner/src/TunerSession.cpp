#include "omnirange_tuner/TunerSession.h"

#include <mrpt/config/CConfigFile.h>

#include <omnirange/config/IniSectionWriter.h>
#include <omnirange/config/LayeredIni.h>
#include <omnirange/io/ObservationImage.h>
#include <omnirange/config/OptionsTable.h>
#include <omnirange/io/Progress.h>
#include <omnirange/config/Output.h>
#include <omnirange/io/RawlogProcessor.h>


#include <algorithm>
#include <chrono>
#include <filesystem>
#include <limits>
#include <map>
#include <stdexcept>

namespace omnirange::tuner
{
namespace
{
constexpr int kFramesTriedAtStart = 20;  // none of the first 20 decodes: the log, not a frame, is bad
}

Agreement agreementOf(const std::vector<RangePair>& pairs)
{
	Agreement a;
	double sum = 0;
	for (const auto& p : pairs)
		if (p.status == PairStatus::Compared) sum += std::abs(p.difference()), ++a.compared;
	a.mean_abs = a.compared ? sum / static_cast<double>(a.compared) : 0.0;
	a.frames = 1;
	return a;
}

TunerSession::TunerSession(SessionOptions options) : o_(std::move(options))
{
	params_ = RangefinderParams::loadFromFile(o_.ini, o_.section);
	for (const auto& base : iniBasesOf(o_.ini)) bases_.push_back(std::filesystem::absolute(base).string());

	// The frames: every omnicam image, with the laser and true scans paired to it.
	std::map<const mrpt::obs::CObservationImage*, std::size_t> index;
	RawlogProcessor loop(o_.rawlog);
	loop.on<mrpt::obs::CObservationImage>(o_.omni_label, [&](const mrpt::obs::CObservationImage::Ptr& image) {
		index[image.get()] = frames_.size();
		frames_.push_back({image, nullptr, nullptr});
	});
	using Scan = mrpt::obs::CObservation2DRangeScan;
	using Image = mrpt::obs::CObservationImage;
	loop.onPair<Image, Scan>(o_.omni_label, o_.laser_label, o_.max_dt,
							 [&](const Image::Ptr& image, const Scan::Ptr& laser) {
								 frames_[index.at(image.get())].laser = laser;
							 });
	loop.onPair<Image, Scan>(o_.omni_label, o_.truth_label, o_.max_dt,
							 [&](const Image::Ptr& image, const Scan::Ptr& truth) {
								 frames_[index.at(image.get())].truth = truth;
							 });
	loop.run();
	images_ = loop.imagesAsOpened();
	if (frames_.empty())
		throw std::runtime_error("no " + o_.omni_label + " image in '" + o_.rawlog + "' (" + loop.describeLabels() + ")");
	saved_ = loaded_ = params_;
	checkImages();
	if (!o_.histogram.empty())
	{
		colours_ = ColourModel::load(o_.histogram);
		rf_ = std::make_unique<Rangefinder>(params_, colours_);
	}
}

// What would make every frame fail is found here, once: a single bad frame
// later is shown as such and the others still work.
void TunerSession::checkImages()
{
	const auto& first = *frames_.front().image;
	if (first.image.isExternallyStored())
	{
		const auto folder = std::filesystem::path(first.image.getExternalStorageFileAbsolutePath()).parent_path();
		if (!std::filesystem::is_directory(folder))
			throw std::runtime_error("the images folder '" + folder.string() + "' of '" + o_.rawlog + "' is missing");
	}
	std::string first_error;
	for (int k = 0; k < std::min(frames(), kFramesTriedAtStart); ++k)
	{
		cv::Mat img;
		try
		{
			img = decodeImage(*frames_[k].image);
		}
		catch (const std::runtime_error& e)
		{
			if (first_error.empty()) first_error = e.what();
			continue;
		}
		// A wrong size is the camera's or the ini's, not one frame's: every frame would fail.
		requireCameraSize(img, *frames_[k].image, params_.camera);
		images_.require();
		cached_bgr_ = img, cached_ = k;
		return;
	}
	throw std::runtime_error(first_error + (frames() > 1 ? " (nor does any of the first frames decode)" : ""));
}

namespace
{
/** Whether every key reads the same in `a` and `b`, as the ini would hold them. */
bool sameValues(const RangefinderParams& a, const RangefinderParams& b)
{
	for (const auto& f : RangefinderParams::table().fields())
		if (f.print(a) != f.print(b)) return false;
	return true;
}
}  // namespace

bool TunerSession::unsaved() const { return !sameValues(params_, saved_); }

const Rangefinder& TunerSession::rangefinder() const
{
	if (!rf_) throw std::logic_error("no colour model yet: open a histogram or train one");
	return *rf_;
}

void TunerSession::setParams(const RangefinderParams& params)
{
	auto rf = hasColours() ? std::make_unique<Rangefinder>(params, colours_) : nullptr;  // validates params
	if (!rf) params.validate();
	if (params.camera.image_width != params_.camera.image_width ||
		params.camera.image_height != params_.camera.image_height)
		cached_ = -1;
	params_ = params;
	rf_ = std::move(rf);
}

LogScore TunerSession::scoreWith(const RangefinderParams& with, const std::function<void(int, int)>& progress)
{
	const RangefinderParams in_force = params_;
	setParams(with);
	try
	{
		LogScore score = scoreAll(progress);
		setParams(in_force);
		return score;
	}
	catch (...)
	{
		setParams(in_force);
		throw;
	}
}

void TunerSession::changeParams(const RangefinderParams& params)
{
	if (sameValues(params, params_)) return;  // no step to undo
	const RangefinderParams before = params_;
	setParams(params);
	undo_.push_back(before);
}

bool TunerSession::undo()
{
	if (undo_.empty()) return false;
	setParams(undo_.back());
	undo_.pop_back();
	return true;
}

void TunerSession::resetToLoaded() { changeParams(loaded_); }

const cv::Mat& TunerSession::image(int k)
{
	if (cached_ != k)
	{
		cv::Mat bgr = decodeImage(*frames_.at(k).image, params_.camera);
		images_.require();  // after decoding: replaced before or while, it is not this frame's picture
		cached_bgr_ = bgr;
		cached_ = k;
	}
	return cached_bgr_;
}

FrameScan TunerSession::scan(int k)
{
	const Frame& f = frames_.at(k);
	FrameScan out;
	out.index = k;
	out.bgr = image(k);
	const auto t0 = std::chrono::steady_clock::now();
	out.scan = rangefinder().process(out.bgr);
	out.scan_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	out.omni = rf_->toObservation(out.scan, f.image->timestamp);
	if (f.laser) out.laser_pairs = pairScans(*f.laser, *out.omni);
	// Against the truth nothing is excluded for being far off: it is the truth.
	if (f.truth) out.truth_pairs = pairScans(*f.truth, *out.omni, 1e9);
	return out;
}

LogScore TunerSession::scoreAll(const std::function<void(int, int)>& progress)
{
	LogScore all;
	const double none = std::numeric_limits<double>::quiet_NaN();
	all.laser_by_frame.assign(static_cast<std::size_t>(frames()), none);
	all.truth_by_frame.assign(static_cast<std::size_t>(frames()), none);
	all.unsure_by_frame.assign(static_cast<std::size_t>(frames()), none);
	double sum = 0;
	for (int k = 0; k < frames(); ++k)
	{
		if (progress) progress(k, frames());
		if (!frames_[k].laser && !frames_[k].truth) continue;
		FrameScan one;
		try
		{
			one = scan(k);
		}
		catch (const std::runtime_error&)  // an unreadable image; the rest of the log still counts
		{
			all.unreadable += frames_[k].laser != nullptr;
			continue;
		}
		all.unsure_by_frame[static_cast<std::size_t>(k)] =
			static_cast<double>(one.scan.count(RayStatus::Unsure)) / std::max<std::size_t>(1, one.scan.rays.size());
		if (const Agreement t = agreementOf(one.truth_pairs); t.compared > 0)
			all.truth_by_frame[static_cast<std::size_t>(k)] = t.mean_abs;
		if (!frames_[k].laser) continue;
		const Agreement a = agreementOf(one.laser_pairs);
		if (a.compared > 0) all.laser_by_frame[static_cast<std::size_t>(k)] = a.mean_abs;
		sum += a.mean_abs * static_cast<double>(a.compared);
		all.compared += a.compared;
		++all.frames;
	}
	images_.require();  // frames left out as unreadable because they were replaced are not the log's
	if (progress) progress(frames(), frames());
	all.mean_abs = all.compared ? sum / static_cast<double>(all.compared) : 0.0;
	return all;
}

RawlogTrainingResult TunerSession::train(const std::string& histogram, TrainingParams training,
										 const std::function<void(std::size_t)>& progress)
{
	images_.require();  // trained on other pictures than the frames shown, the model would not be theirs
	RawlogTrainingOptions o;
	o.input = o_.rawlog;
	o.omni_label = o_.omni_label;
	o.laser_label = o_.laser_label;
	o.max_dt = o_.max_dt;
	o.training = training;
	Progress shown("objects read (training)", [&](std::size_t done, std::size_t) {
		if (progress) progress(done);
	});
	RawlogTrainingResult r = trainFromRawlog(params_, o, progress ? &shown : nullptr);
	r.model.save(histogram);
	colours_ = r.model;
	rf_ = std::make_unique<Rangefinder>(params_, colours_);
	o_.histogram = histogram;
	return r;
}

void TunerSession::requireSaveAllowed(const std::string& ini)
{
	namespace fs = std::filesystem;
	std::error_code ec;
	// An ini there when the window opened (the -c one, or --save-to's) and gone or emptied now: a save would
	// make one of the window's changed keys alone, while the window shows the rest as they were.
	const std::string key = fs::absolute(ini, ec).lexically_normal().string();
	const auto keysIn = [&] {
		if (!fs::exists(ini, ec)) return -1;
		try
		{
			return requireWellFormedIni(ini);
		}
		catch (const std::exception&)
		{
			return 1;  // something there, refused as it is below
		}
	};
	const bool own = key == fs::absolute(o_.ini, ec).lexically_normal().string();
	const std::string leads_to = fileLedTo(ini);
	save_targets_.emplace(key, SaveTarget{own ? std::max(1, keysIn()) : keysIn(), leads_to});  // -c: read with its keys
	const int then = save_targets_.at(key).keys, now = keysIn();
	if (then >= 0 && now < 0)
		throw std::runtime_error("'" + ini + "' was moved or removed since the window opened: a new one would hold " +
								 "none of its other keys; put it back, then save");
	if (then > 0 && now == 0)
		throw std::runtime_error("'" + ini + "' holds no key now, emptied since the window opened: a save would " +
								 "hold none of its other keys; put them back, then save");
	std::vector<std::string> inputs{o_.rawlog, o_.histogram};
	inputs.insert(inputs.end(), bases_.begin(), bases_.end());
	requireOutputAllowed(ini, OutputKind::Ini, "omnirange-tuner", inputs);
	// Made a link to another file meanwhile (another camera's ini, a user's notes): that file was never given.
	requireStillLeadsTo(ini, save_targets_.at(key).leads_to, "the window opened");
	RangefinderParams::requireWritable(ini, o_.section);
}

void TunerSession::saveIni(const std::string& ini)
{
	const std::string target = ini.empty() ? o_.ini : ini;
	requireSaveAllowed(target);  // the files may have changed since the start
	// Only the keys changed here since the ini was read or last saved: every
	// other line stays as the user wrote it, an edit made in the file meanwhile
	// too. Into another ini: the keys whose value differs from what it gives now
	// (through its base, or the defaults).
	std::error_code ec;
	const bool own = std::filesystem::equivalent(target, o_.ini, ec);
	RangefinderParams given = saved_;
	if (!own)
	{
		given = RangefinderParams();
		if (std::filesystem::exists(target) && mrpt::config::CConfigFile(target).sectionExists(o_.section))
			given = RangefinderParams::loadFromFile(target, o_.section);
	}
	std::vector<std::pair<std::string, std::string>> values;
	for (const auto& f : RangefinderParams::table().fields())
		if (f.print(params_) != f.print(given)) values.emplace_back(f.info.key, f.print(params_));
	if (!values.empty()) writeIniSection(target, o_.section, values, RangefinderParams::table().comments());
	saved_ = params_;
}

}  // namespace omnirange::tuner
