#pragma once
// icp-slam's configuration as MRPT 2.5 reads it. MRPT reads only the keys it
// knows and ignores the rest without a word, so an option under an old name
// (MRPT's own icp-slam templates still write onlyClosestCorrespondences,
// which 2.5 does not read) silently keeps its default.

#include <string>
#include <vector>

namespace omnirange::slam
{
/** The keys of `section` in the ini file `file` that MRPT's ICP options
 * (mrpt::slam::CICP::TConfigParams) do not read, sorted; throws if the file
 * cannot be read or has no such section. */
std::vector<std::string> icpKeysMrptIgnores(const std::string& file, const std::string& section = "ICP");

/** The ini read strictly, as every ini of ours is: no key repeated in a
 * section; in [ICP] only keys MRPT reads, each value of the kind MRPT's
 * default is (a number without unit or decimal comma, true/false, or an
 * enum's name). Throws std::runtime_error naming the file, section and key. */
void requireStrictIcpSection(const std::string& file, const std::string& section = "ICP");

/** [MappingApplication] logOutput_dir of the MRPT ini `file` (icp-slam's or
 * rbpf-slam's), which the program empties before it writes there. Throws
 * std::runtime_error naming the file unless it is a plain folder name (no
 * '/', not '.' or '..'), made where the program runs. */
std::string mrptLogFolder(const std::string& file);

/** The [MappingApplication] settings of `file` that icp-slam follows and
 * omnirange's guarded matcher does not (it matches each scan against a points
 * map of its keyframes, from the rawlog's first entry), as "key = value":
 * rawlog_offset other than 0, matchAgainstTheGrid true, pointsMap_count other
 * than 1. */
std::vector<std::string> mappingSettingsGuardedIcpIgnores(const std::string& file);

}  // namespace omnirange::slam
