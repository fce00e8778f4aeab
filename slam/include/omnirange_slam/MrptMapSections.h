#pragma once
// The map sections of an MRPT ini ([MappingApplication_occupancyGrid_00_insertOpts]
// and the like) as MRPT 2.5 reads them. MRPT reads the keys it knows, with
// C's atof and atoi, and ignores the rest: a misspelt key keeps its default,
// "0,05" reads as 0, "maybe" as false. So the keys MRPT reads are recorded as
// it reads them (a config source that notes each key asked for, with its
// default), and the ini is held to them.

#include <string>

namespace omnirange::slam
{
/** What any value MRPT reads may be beyond its default's kind. */
struct MrptValueBounds
{
	double largest;  ///< |value| at most this
	bool keep_sign;  ///< a key whose default is >= 0 takes no negative value
};

/** Throws std::invalid_argument (the reason only; the caller names file,
 * section and key) unless `value` is of the kind of MRPT's default `model`
 * for `key`, as MRPT wrote or read it: true/false or 0/1 for a bool, a whole
 * number for an int, a number without unit or decimal comma, an enum's name
 * or number, a plain name; and within the key's own range where MRPT asserts
 * one or memory sets one (resolution, extents, sample sizes, alfa, ...). */
void requireLikeMrptsDefault(const std::string& key, const std::string& model, const std::string& value,
							 const MrptValueBounds& bounds);

/** Throws std::runtime_error naming the file, section and key when a section
 * `prefix`_KIND_NN_OPTS is one MRPT would not read (misspelt, or past the
 * map's count), a key in it is not one MRPT reads, or a value is not of the
 * kind of MRPT's default (a number without unit or decimal comma, a whole
 * number where MRPT reads an int, true/false); also a map count that is not
 * a whole number within [0, 16], a resolution that is not > 0, and an
 * occupancy update certainty outside [0.5, 1). */
void requireStrictMapSections(const std::string& file, const std::string& prefix = "MappingApplication");

/** The same for a whole observations2map ini: its only sections are the map
 * list's and its maps', its only keys those MRPT reads there. */
void requireStrictObservationsToMapIni(const std::string& file);

/** The same for a whole rbpf-slam ini: [MappingApplication] holds the keys
 * the filter, its maps and its options read (recorded as MRPT reads them:
 * sampleSize within [1, 10000], PF_algorithm one of its four, ...) and
 * rbpf-slam's own (rawlog_offset, logOutput_dir, ...); the map sections
 * as above. */
void requireStrictRbpfIni(const std::string& file);

}  // namespace omnirange::slam
