#pragma once
// The one loop over a rawlog (the shape of MRPT's CRawlogProcessor): it
// streams the file object by object (RawlogReader: memory does not grow with
// its length, a truncated file or an unknown class is an error), opens the
// actions/sensory-frames format's frames into their observations, and calls
// the hooks registered for a class and a sensor label. Every reader of a
// rawlog in this project is a few hooks over this loop.
//
//   RawlogProcessor loop(path);
//   loop.on<CObservationRobotPose>("GT", [&](const auto& gt) { ... });
//   loop.onPair<CObservationImage, CObservation2DRangeScan>("OMNICAM", "LASER", max_dt,
//       [&](const auto& image, const auto& scan) { ... });
//   loop.run(&progress);

#include <omnirange/io/ObservationPairer.h>
#include <omnirange/io/RawlogReader.h>

#include <mrpt/obs/CObservation.h>

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace omnirange
{
class Progress;

class RawlogProcessor
{
   public:
	using ObjectHook = std::function<void(const mrpt::serialization::CSerializable::Ptr&)>;
	using ObservationHook = std::function<void(const mrpt::obs::CObservation::Ptr&)>;

	/** Opens `path`; throws std::runtime_error if it cannot. */
	explicit RawlogProcessor(const std::string& path);

	/** `hook(obs)` for every observation of class T whose label is `label`
	 * (empty: any label). */
	template <class T>
	void on(const std::string& label, std::function<void(const std::shared_ptr<T>&)> hook)
	{
		onObservation([label, hook = std::move(hook)](const mrpt::obs::CObservation::Ptr& o) {
			if (!label.empty() && o->sensorLabel != label) return;
			if (auto t = std::dynamic_pointer_cast<T>(o)) hook(t);
		});
	}

	/** `hook(a, b)` for every pair of an A labelled `label_a` and a B
	 * labelled `label_b` taken within max_dt of each other (ObservationPairer). */
	template <class A, class B>
	void onPair(const std::string& label_a, const std::string& label_b, double max_dt,
				std::function<void(const std::shared_ptr<A>&, const std::shared_ptr<B>&)> hook)
	{
		auto pairer = std::make_shared<ObservationPairer<A, B>>(label_a, label_b, max_dt);
		no_pair_.push_back([pairer] { return pairer->describeNoPair(); });
		onObservation([pairer, hook = std::move(hook)](const mrpt::obs::CObservation::Ptr& o) {
			if (pairer->add(o)) hook(pairer->first(), pairer->second());
		});
	}

	/** `hook(obs)` for every observation, in file order. */
	void onObservation(ObservationHook hook) { observation_hooks_.push_back(std::move(hook)); }
	/** `hook(obj)` for every object as read (an observation, a sensory frame,
	 * an action collection), before the observation hooks see its observations. */
	void onObject(ObjectHook hook) { object_hooks_.push_back(std::move(hook)); }

	/** Streams to the end, or until a hook calls stop(). Throws
	 * std::runtime_error on a truncated or corrupt rawlog; a hook's exception
	 * passes through. `progress` counts objects read. */
	void run(Progress* progress = nullptr);
	void stop() { stopped_ = true; }

	std::size_t objectsRead() const { return reader_.objectsRead(); }
	const std::string& path() const { return reader_.path(); }
	/** RawlogReader::requireImagesUnchanged(): for images decoded after run(). */
	void requireImagesUnchanged() const { reader_.requireImagesUnchanged(); }
	const ImagesAsOpened& imagesAsOpened() const { return reader_.imagesAsOpened(); }
	/** "the labels found: A, B" or "no observation at all", for errors. */
	std::string describeLabels() const;
	/** Why a registered onPair() found nothing, naming the file and its labels. */
	std::string describeNoPair() const;

   private:
	RawlogReader reader_;
	std::vector<ObjectHook> object_hooks_;
	std::vector<ObservationHook> observation_hooks_;
	std::vector<std::function<std::string()>> no_pair_;
	std::set<std::string> labels_;
	bool stopped_{false};
};

}  // namespace omnirange
