// The N/K filters on scanlines written as strings: 'F' free, 'X' not free.
// The first character is the pixel at the robot base, the last the outermost.
#include <omnirange/core/HitFilter.h>

#include <gtest/gtest.h>

#include <string>

using namespace omnirange;
using Status = HitSearch::Status;

namespace
{
HitSearch search(const std::string& line, int N, int K, int last_candidate = -1)
{
	const int n = static_cast<int>(line.size());
	return findHit(
		[&](int i) { return line.at(static_cast<std::size_t>(i)) == 'F'; }, n,
		last_candidate < 0 ? n - 1 : last_candidate, HitFilterParams{N, K});
}
}  // namespace

TEST(HitFilter, PaperFig3aFalsePositiveFilter)
{
	// N = 4: the X is a hit because the 4 pixels behind it are X too.
	const auto r = search("FFFXXXXXFF", 4, 2);
	EXPECT_EQ(r.status, Status::Hit);
	EXPECT_EQ(r.index, 3);
	// Only 3 X behind the first X, then real floor: not a hit there.
	EXPECT_EQ(search("FFFXXXXFFFFFFF", 4, 2).status, Status::NoCandidate);
}

TEST(HitFilter, PaperFig3bFalseNegativeFilter)
{
	// K = 2: X F X then F F F. The lone F is negated (an X follows it), but
	// the run of K+1 = 3 F rejects the candidate; the search resumes after
	// that run and finds the wall at index 10.
	const auto r = search("FFXFXFFFFFXXXXXXX", 4, 2);
	EXPECT_EQ(r.status, Status::Hit);
	EXPECT_EQ(r.index, 10);
}

TEST(HitFilter, MisclassifiedFreePixelsInsideAWallAreNegated)
{
	EXPECT_EQ(search("FFFXXFXXXX", 4, 2).index, 3);
	EXPECT_EQ(search("FFFXFFXXXX", 4, 2).index, 3);  // a run of exactly K
	EXPECT_EQ(search("FFFXFXFXFXF", 4, 2).index, 3);  // alternating noise
	// A run of K+1 free pixels is floor: rejected.
	EXPECT_EQ(search("FFFXFFFXXXXX", 4, 2).index, 7);
}

TEST(HitFilter, MisclassifiedWallPixelsOnTheFloorAreIgnored)
{
	EXPECT_EQ(search("FFXFFFFFFFXXXXX", 4, 2).index, 10);
	EXPECT_EQ(search("FXXFFFXXXFFFFFFFFXXXXXX", 4, 2).index, 17);
}

TEST(HitFilter, KZeroRejectsOnAnyFreePixel)
{
	EXPECT_EQ(search("FXXFXXXXXX", 4, 0).index, 4);
	EXPECT_EQ(search("FXXFXXXXXX", 4, 1).index, 1);
}

TEST(HitFilter, NOneNeedsOnlyTheNextPixel)
{
	EXPECT_EQ(search("FFXXF", 1, 0).index, 2);
	EXPECT_EQ(search("FFXFF", 1, 0).status, Status::NoCandidate);
}

TEST(HitFilter, FirstPixelCanBeTheHit)
{
	const auto r = search("XXXXXX", 4, 2);
	EXPECT_EQ(r.status, Status::Hit);
	EXPECT_EQ(r.index, 0);
}

TEST(HitFilter, EmptyAndAllFreeScanlines)
{
	EXPECT_EQ(search("", 4, 2).status, Status::NoCandidate);
	EXPECT_EQ(search("FFFFFFFFFFFF", 4, 2).status, Status::NoCandidate);
}

TEST(HitFilter, CandidateNearTheEndOfTheScanline)
{
	// The window runs off the end before N pixels confirm it.
	auto r = search("FFFFFXXX", 4, 2);
	EXPECT_EQ(r.status, Status::Unconfirmed);
	EXPECT_EQ(r.index, 5);
	// A short free run reaching the end cannot be negated either.
	EXPECT_EQ(search("FFFFFXXXFF", 4, 2).status, Status::Unconfirmed);
	// Exactly N pixels after it: confirmed.
	EXPECT_EQ(search("FFFFFXXXXX", 4, 2).index, 5);
}

TEST(HitFilter, CandidatesBeyondTheLastAllowedAreIgnored)
{
	// Scanning past the max-range radius only confirms earlier candidates.
	EXPECT_EQ(search("FFFFFXXXXXXX", 4, 2, 4).status, Status::NoCandidate);
	EXPECT_EQ(search("FFFFFXXXXXXX", 4, 2, 5).index, 5);
}

TEST(HitFilter, ClassifiesLazily)
{
	const std::string line = "FFFXXXXX" + std::string(100, 'F');
	int calls = 0;
	const auto r = findHit(
		[&](int i) { return ++calls, line[static_cast<std::size_t>(i)] == 'F'; },
		static_cast<int>(line.size()), static_cast<int>(line.size()) - 1,
		HitFilterParams{4, 2});
	EXPECT_EQ(r.index, 3);
	EXPECT_LE(calls, 8);  // pixels 0..7 decide it
}

TEST(HitFilter, TheSearchKeepsTheCandidatesKRejectedAndWhy)
{
	// K = 1: the X at 2 is followed by FF (a run of K+1): rejected; the X at 5 is the hit.
	auto r = search("FFXFFXXXXX", 3, 1);
	EXPECT_EQ(r.status, Status::Hit);
	EXPECT_EQ(r.index, 5);
	EXPECT_EQ(r.rejected_by_K, 1);
	EXPECT_EQ(r.last_rejected, 2);
	// A candidate whose window runs off the scanline stays named.
	r = search("FFFFFFFXX", 4, 1);
	EXPECT_EQ(r.status, Status::Unconfirmed);
	EXPECT_EQ(r.index, 7);
	EXPECT_EQ(r.rejected_by_K, 0);
	r = search("FFXFFFXFFFF", 4, 1);
	EXPECT_EQ(r.status, Status::NoCandidate);
	EXPECT_EQ(r.index, -1);
	EXPECT_EQ(r.rejected_by_K, 2);
	EXPECT_EQ(r.last_rejected, 6);
}
