#pragma once
// The colours the rangefinder knows: the free floor's histogram (the
// paper's, §III-A) and, where training saw them, the obstacles' (the colours
// just beyond the laser's hits). With both, a colour is free floor only when
// the floor explains it at least as well as the obstacles do (a two-class
// model): a wall the colour of a shadowed patch of floor stops being free
// when training has seen that wall.

#include <omnirange/core/ColourHistogram.h>

#include <array>
#include <string>

namespace omnirange
{
struct ColourModel
{
	ColourHistogram floor;
	ColourHistogram obstacles;  ///< empty: the one-class model of the paper
	/** Median B, G, R of the floor just beyond the base during training
	 * (ExposureCompensation.h); all 0 when unknown. */
	std::array<double, 3> reference{};

	/** A one-class model: the floor only. */
	ColourModel(ColourHistogram floor_histogram = ColourHistogram())  // NOLINT: implicit on purpose
		: floor(std::move(floor_histogram)), obstacles(floor.space(), floor.binsPerChannel())
	{
	}
	ColourModel(ColourHistogram floor_histogram, ColourHistogram obstacle_histogram);

	bool hasObstacles() const { return !obstacles.empty(); }
	bool hasReference() const { return reference[0] + reference[1] + reference[2] > 0; }
	/** Whether training saw a floor of colour: its reference's channels
	 * differ by more than a grey floor's do in colour JPEGs. Grey images
	 * (three equal channels) hold none of what it learned. */
	bool trainedOnColour() const;

	/** One file: the floor histogram's bytes, then the obstacles' if any
	 * (each versioned and checksummed, ColourHistogram's format), then the
	 * reference colour if known ("OMNIREF1" and three little-endian
	 * doubles). Written atomically. */
	void save(const std::string& path) const;
	/** What save() writes. */
	std::string serialize() const;
	/** Reads a file written by save(), or a plain histogram file (then
	 * one-class); throws std::runtime_error naming the file. */
	static ColourModel load(const std::string& path);
};

}  // namespace omnirange
