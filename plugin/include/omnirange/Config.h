#pragma once
// Small helpers shared by the options structs that load from ini files.

#include <string>
#include <vector>

namespace mrpt::config
{
class CConfigFileBase;
}

namespace omnirange
{
/** Throws std::invalid_argument if `section` holds a key not in `known`,
 * naming the key and the section (a misspelt key must not pass silently). */
void requireKnownKeys(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::vector<std::string>& known);

/** Throws std::invalid_argument("<section>: <what>") unless `ok`. */
void requireParam(bool ok, const std::string& section, const std::string& what);

}  // namespace omnirange
