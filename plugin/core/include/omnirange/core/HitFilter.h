#pragma once
// The hit search along one scanline with the paper's false-positive (N) and
// false-negative (K) filters (§III-B1, Fig. 3; semantics in docs/method.md).
//
// Pixel 0 is the scanline's first pixel (at the robot base's radius); pixels
// are visited outwards. The first non-free pixel is a candidate. Behind it
// (further out) a run of free pixels is negated, counted as non-free, while it
// is at most K long; a run of K+1 free pixels rejects the candidate and the
// search goes on after that run. The candidate becomes the hit once N pixels
// behind it count as non-free.

#include <string>

namespace omnirange
{
struct HitFilterParams
{
	int N{20};  ///< [px] non-free pixels that must follow a candidate (>= 1)
	int K{2};  ///< [px] longest free run negated inside the window (>= 0)
};

/** What the search along one scanline found, and why: a tuner or a test can
 * show a user which candidates the filters turned down. */
struct HitSearch
{
	enum class Status
	{
		Hit,  ///< index is the hit pixel
		NoCandidate,  ///< no (further) non-free pixel at or before last_candidate
		Unconfirmed  ///< index is a candidate whose window ran off the end of the scanline
	};
	Status status{Status::NoCandidate};
	int index{-1};  ///< the hit, or the unconfirmed candidate; -1 if none
	int rejected_by_K{0};  ///< candidates rejected by a run of K+1 free pixels behind them
	int last_rejected{-1};  ///< the last of those candidates; -1 if none
};
std::string toString(HitSearch::Status s);

/** Searches pixels [0, count) of one scanline; `is_free(i)` classifies pixel
 * i (called lazily: pixels past the decision are never classified). Candidates beyond
 * `last_candidate` are not considered. */
template <class IsFree>
HitSearch findHit(
	IsFree&& is_free, int count, int last_candidate, const HitFilterParams& p)
{
	HitSearch out;
	const auto finish = [&](HitSearch::Status s, int index) {
		out.status = s, out.index = index;
		return out;
	};
	int i = 0;
	for (;;)
	{
		// 1. The next candidate: the first non-free pixel from i on.
		while (i < count && i <= last_candidate && is_free(i)) ++i;
		if (i >= count || i > last_candidate) return finish(HitSearch::Status::NoCandidate, -1);
		const int candidate = i;

		// 2. Confirm it with N non-free pixels behind it (Fig. 3a), negating
		//    free runs of at most K pixels (Fig. 3b).
		int confirmed = 0;
		int j = candidate + 1;
		bool rejected = false;
		while (confirmed < p.N)
		{
			if (j >= count) return finish(HitSearch::Status::Unconfirmed, candidate);
			if (!is_free(j))
			{
				++confirmed, ++j;
				continue;
			}
			int run = 1;  // pixel j is free; measure its run up to K+1
			while (run <= p.K && j + run < count && is_free(j + run)) ++run;
			if (run > p.K)
			{
				rejected = true;  // K+1 free pixels: real free space goes on
				++out.rejected_by_K, out.last_rejected = candidate;
				i = j + run;
				break;
			}
			if (j + run >= count) return finish(HitSearch::Status::Unconfirmed, candidate);
			confirmed += run;  // negated: a short free run counts as non-free
			j += run;
		}
		if (!rejected) return finish(HitSearch::Status::Hit, candidate);
	}
}

}  // namespace omnirange
