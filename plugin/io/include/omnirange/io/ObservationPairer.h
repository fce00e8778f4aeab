#pragma once
// Pairs two kinds of observation taken together (an omnicam image with the
// laser scan of the same moment, a laser scan with an omnicam scan) while a
// rawlog streams by. The latest of each kind is held; the two pair up when
// their timestamps differ by at most max_dt, and each observation pairs once.

#include "omnirange/config/OptionsTable.h"

#include <mrpt/obs/CObservation.h>
#include <mrpt/system/datetime.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace omnirange
{
/** [s] largest time between two observations that pair up (default 0.1:
 * less than half the frame period of the robots this project simulates). */
constexpr double kDefaultMaxPairingDt = 0.1;
/** [s] the pairing times a user may ask for: an image and a scan a minute
 * apart are not the same moment, and 1e300 s would pair a whole log at once. */
constexpr Range kPairingDtRange = Range::closed(0, 60);

inline void requirePairingDt(double max_dt)
{
	if (!kPairingDtRange.contains(max_dt))
		throw std::invalid_argument("max_dt must be " + kPairingDtRange.text() + " s");
}

template <class A, class B>
class ObservationPairer
{
   public:
	ObservationPairer(std::string label_a, std::string label_b, double max_dt = kDefaultMaxPairingDt)
		: label_a_(std::move(label_a)), label_b_(std::move(label_b)), max_dt_(max_dt)
	{
		requirePairingDt(max_dt);
	}

	/** Feeds the next observation; true when it completes a pair, which first()
	 * and second() then hold until the next call. */
	bool add(const mrpt::obs::CObservation::Ptr& obs)
	{
		if (paired_) a_.reset(), b_.reset(), paired_ = false;
		if (auto a = std::dynamic_pointer_cast<A>(obs); a && obs->sensorLabel == label_a_)
			a_ = std::move(a);
		else if (auto b = std::dynamic_pointer_cast<B>(obs); b && obs->sensorLabel == label_b_)
			b_ = std::move(b);
		else
			return false;
		paired_ = a_ && b_ && std::abs(mrpt::system::timeDifference(a_->timestamp, b_->timestamp)) <= max_dt_;
		return paired_;
	}

	const std::shared_ptr<A>& first() const { return a_; }
	const std::shared_ptr<B>& second() const { return b_; }

	/** "no A observation had a partner labelled B within DT s", for errors. */
	std::string describeNoPair() const
	{
		char dt[32];
		std::snprintf(dt, sizeof dt, "%g", max_dt_);
		return "no " + label_a_ + " observation had a partner labelled " + label_b_ + " within " + dt + " s";
	}

   private:
	std::string label_a_, label_b_;
	double max_dt_;
	std::shared_ptr<A> a_;
	std::shared_ptr<B> b_;
	bool paired_{false};
};

}  // namespace omnirange
