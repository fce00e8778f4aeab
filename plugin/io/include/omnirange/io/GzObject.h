#pragma once
// One MRPT object stored alone in a gzip file, as MRPT's programs write grid
// maps (.gridmap.gz) and simplemaps: read the same way wherever one is read.

#include <omnirange/config/OptionsTable.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace omnirange
{
/** The object of type T in the gzip file `path`; throws std::runtime_error
 * naming the `what` and the file if it is not a regular file or cannot be
 * opened (MRPT's own exception if what it holds is not a T). */
template <class T>
T readGzObject(const std::string& path, const std::string& what)
{
	requireRegularFile(path, what);
	if (!std::filesystem::exists(path)) throw std::runtime_error(what + " '" + path + "' is missing");
	mrpt::io::CFileGZInputStream f;
	if (!f.open(path)) throw std::runtime_error("cannot open " + what + " '" + path + "'");
	T object;
	mrpt::serialization::archiveFrom(f) >> object;
	return object;
}

}  // namespace omnirange
