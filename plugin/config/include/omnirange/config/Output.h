#pragma once
// What every program may write, and how it puts it in place.
//
// The guarantee:
//  - an output replaces only what the same program wrote before: a file of
//    the output's own kind (told by its first bytes), or a folder whose
//    marker (kOutputMarker: the program's name and the files it wrote)
//    names the program and lists everything in it; anything else is refused
//    with one line naming it, unless the user says --force;
//  - no output is, holds or sits inside an input, through links, bind
//    mounts and hard links;
//  - a killed or failed run leaves the old output whole and nothing that
//    looks whole; the files of one run go in together.
//
// One mechanism keeps the last: a run stages everything it writes in one
// hidden folder beside the outputs (mkdtemp, held by flock while the run
// lives), then commits: the list of what goes in is written to the staging
// folder, each file is renamed into place and each folder exchanged with the
// old one (renameat2), folders first and then files (the file that names the others
// last). A staging folder whose lock is free is a run's that ended before it
// could remove it (killed, interrupted, ended by a library): the next run
// writing beside it, or reading an input there, finishes its commit if the
// list was written (each listed entry not yet in is moved in), else removes it.

#include "omnirange/config/Files.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace omnirange
{
/** The file a folder written by one of our programs holds: the program's
 * name on its first line, then "file REL" for every file it wrote. */
inline constexpr const char* kOutputMarker = ".omnirange-output";

enum class OutputKind
{
	Rawlog,  ///< a gzip file holding MRPT objects
	GridMap,  ///< a gzip file holding an MRPT COccupancyGridMap2D (.gridmap.gz)
	Histogram,  ///< a colour model (ColourHistogram's "OMNIHIST" magic)
	Ini,  ///< text whose first line that is not blank is a comment, a section or a key
	Text,  ///< text (CSV, Markdown): no NUL byte
	Image,  ///< PNG or JPEG
	Folder  ///< a folder holding kOutputMarker
};

struct Output
{
	std::string path;
	OutputKind kind;
	/** A text output its program always begins so: an existing file must
	 * begin so too (a user's notes.md is text, but not a summary). */
	std::string begins_with{};
};

/** `path` as a user means it: no trailing '/', "." resolved; "" stays "". */
std::string outputPath(const std::string& path);
/** Whether the existing file `path` is of `kind`, told by its first bytes. */
bool isOfKind(const std::string& path, OutputKind kind);

/** Throws std::runtime_error, one line, before any work, when the guarantee
 * forbids `program` to write one of `outputs` ("" paths skipped), or two of
 * them are one place. With `force`, an existing file or folder of another's
 * may be replaced (a folder is kept, renamed NAME.replaced), never an input.
 * First finishes what killed runs left beside the inputs: no run reads a set
 * a kill left half in place. */
void requireOutputsAllowed(const std::vector<Output>& outputs, const std::string& program,
						   const std::vector<std::string>& inputs, bool force = false);
inline void requireOutputAllowed(const std::string& path, OutputKind kind, const std::string& program,
								 const std::vector<std::string>& inputs, bool force = false)
{
	requireOutputsAllowed({{path, kind}}, program, inputs, force);
}

/** A file read to be updated changed before the update went in (another
 * run's, a user's editor): nothing was replaced. */
class ChangedMeanwhile : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

/** The outputs of one run, staged and committed together (see above).
 * Destroyed uncommitted, its staging folders are removed. */
class OutputSet
{
   public:
	/** With a `program`, commit() checks the guarantee again for every
	 * output (a user may have made or filled one while the run went). */
	explicit OutputSet(std::string program = "", std::vector<std::string> inputs = {}, bool force = false);
	~OutputSet();
	OutputSet(const OutputSet&) = delete;
	OutputSet& operator=(const OutputSet&) = delete;

	/** Where the run writes `output` (a file, or a folder it makes there):
	 * a path in the staging folder beside it. A link is written through.
	 * commit() puts the outputs in in the order staged: the one that names
	 * the others (a rawlog, its images) last. */
	std::string stage(const Output& output);
	/** Stages the file `output` by calling `writer(staged_path)`. */
	void write(const Output& output, const std::function<void(const std::string&)>& writer);
	/** Stages the file `output` holding `bytes`. */
	void write(const Output& output, const std::string& bytes);
	/** commit() throws ChangedMeanwhile, replacing nothing, unless `path` is
	 * still as fileStateOf() said when it was read. */
	void requireUnchanged(const std::string& path, const std::string& state);
	/** Puts every staged output in place. */
	void commit();
	/** Leaves the staging folders for a look (a failed run's work): the next
	 * run beside them removes them. */
	void keep() { kept_ = true; }

   private:
	struct Staged;
	struct Folder;
	Folder& folderFor(const std::string& parent, const std::string& output);
	void ready(const Staged& s) const;
	void writeLists(const std::vector<const Staged*>& order) const;
	void placeUpdate(const Staged& s) const;
	std::string program_;
	std::vector<std::string> inputs_;
	bool force_{false}, done_{false}, kept_{false};
	std::vector<Staged> staged_;
	std::vector<Folder> folders_;
};

/** `bytes` written to `path` atomically (a one-file OutputSet). */
void writeFileAtomically(const std::string& path, const std::string& bytes);
}  // namespace omnirange
