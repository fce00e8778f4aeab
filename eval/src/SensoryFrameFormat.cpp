#include "omnirange_eval/SensoryFrameFormat.h"

#include <omnirange/io/RawlogProcessor.h>
#include <omnirange/io/RawlogWriter.h>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>

namespace omnirange::eval
{
int writeSensoryFrameFormat(const std::string& in, const std::string& out, const std::string& odometry_label)
{
	RawlogWriter w(out, "omnirange-experiment");
	w.shareImagesOf(imagesDirToRead(in));
	std::optional<mrpt::poses::CPose2D> last_odo;
	mrpt::obs::CSensoryFrame frame;
	mrpt::obs::CActionCollection action;
	int frames = 0;
	const auto flush = [&] {
		if (frame.size() == 0) return;
		w.write(action);
		w.write(frame);
		frame.clear();
		action = mrpt::obs::CActionCollection();
		++frames;
	};
	RawlogProcessor loop(in);
	loop.onObservation([&](const mrpt::obs::CObservation::Ptr& obs) {
		const auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs);
		if (!odo || odo->sensorLabel != odometry_label)
		{
			frame.insert(obs);
			return;
		}
		flush();
		mrpt::obs::CActionRobotMovement2D move;
		move.timestamp = odo->timestamp;
		move.computeFromOdometry(last_odo ? odo->odometry - *last_odo : mrpt::poses::CPose2D(),
								 mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
		action.insert(move);
		last_odo = odo->odometry;
	});
	loop.run();
	flush();
	w.commit();
	return frames;
}

}  // namespace omnirange::eval
