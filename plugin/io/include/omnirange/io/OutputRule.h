#pragma once
// The one rule for what a program may write over, for every program:
//  - an output replaces only what the same program wrote before: a folder
//    it made holds a marker file naming the program (kOutputMarker); a file
//    must be of the output's own kind, told by its first bytes;
//  - any other existing file, or a non-empty folder, is refused with one
//    line naming it, unless the user says --force;
//  - no output may be, contain or sit inside an input, through symlinks.
// Paths are taken as a user types them: "out/" is the folder "out".

#include <functional>
#include <string>
#include <vector>

namespace omnirange
{
/** The file a folder made by one of our programs holds: the program's name. */
inline constexpr const char* kOutputMarker = ".omnirange-output";

enum class OutputKind
{
	Rawlog,  ///< a gzip file (MRPT's rawlogs as we write them)
	GridMap,  ///< a gzip file holding an MRPT COccupancyGridMap2D (.gridmap.gz)
	Histogram,  ///< a colour model (ColourHistogram's "OMNIHIST" magic)
	Ini,  ///< text whose first line that is not blank is a comment, a section or a key
	Text,  ///< text (CSV, Markdown): no NUL byte
	Image,  ///< PNG or JPEG
	Folder  ///< a folder holding kOutputMarker
};

/** Whether the existing file `path` is of `kind`, told by its first bytes
 * (Folder: never; use isOutputFolderOf()). */
bool isOfKind(const std::string& path, OutputKind kind);

/** `path` as a user means it: no trailing '/', "." resolved; "" stays "". */
std::string outputPath(const std::string& path);
/** The file `path` leads to, links resolved (what a save into it would write). */
std::string fileLedTo(const std::string& path);
/** `path` leads to `was` (its fileLedTo() when `since` began) still: a save made a link to another file
 * meanwhile would write that file, never given. Throws std::runtime_error naming both otherwise. */
void requireStillLeadsTo(const std::string& path, const std::string& was, const std::string& since);

/** Throws std::runtime_error, before any work, naming `output` when the rule
 * above forbids `program` to write it. With `force`, an existing file or
 * folder of another kind may be replaced, but never an input. A text or ini
 * output whose program always begins it the same way gives `begins_with`: an
 * existing file must begin so too (a user's notes.md is text, but not a
 * summary). */
void requireOutputAllowed(const std::string& output, OutputKind kind, const std::string& program,
						  const std::vector<std::string>& inputs, bool force = false,
						  const std::string& begins_with = "");

/** requireOutputAllowed()'s check against `inputs` alone (throws naming
 * one the output is, holds or lies in, through links, bind mounts and hard
 * links): for what a run checks again just before it writes, once it has
 * staged temporaries that the whole check would take for leftovers. */
void requireApartFromInputs(const std::string& output, OutputKind kind, const std::vector<std::string>& inputs);

struct Output
{
	std::string path;
	OutputKind kind;
	std::string begins_with{};  ///< see requireOutputAllowed()
};
/** Throws std::runtime_error naming two of `paths` that are one place, or
 * one inside the other, through symlinks: the second would replace the first. */
void requireDistinctOutputs(const std::vector<std::string>& paths);

/** requireDistinctOutputs() and requireOutputAllowed() for each of a
 * program's outputs ("" paths skipped). */
void requireOutputsAllowed(const std::vector<Output>& outputs, const std::string& program,
						   const std::vector<std::string>& inputs, bool force = false);

/** Throws std::runtime_error, one line, when `output` is (or holds) a file
 * that a folder around it, marked by another program than `program`, lists
 * as its own (a report's histogram, its dataset): replacing it would leave
 * that folder's other files and figures about other data. A folder this run
 * made is its own to fill. */
void requireNotAnothersPart(const std::string& output, const std::string& program);

/** The lines of the marker in the folder `dir`: none when there is no
 * marker, or what is there is not a plain file (a FIFO, a link) or is
 * larger than any marker of ours. Every reader of markers reads them so. */
std::vector<std::string> markerLines(const std::string& dir);

/** Appends `line` to the marker of the folder `dir` (what its run, its
 * files, its rawlog or its moving aside were); throws naming the marker.
 * With `create` false, a folder without a marker is refused, not marked. */
void noteInMarker(const std::string& dir, const std::string& line, bool create = true);
/** Takes `line` out of the marker of `dir` (the marker rewritten whole);
 * false, and nothing written, when the marker does not have it (the folder
 * was moved or replaced meanwhile: no marker is made in a user's folder). */
bool unnoteInMarker(const std::string& dir, const std::string& line);
/** What the marker of `dir` says after "KEY " on its first line so begun
 * ("" if none): "pending PID" (a folder moved in before the file it belongs
 * with, RawlogWriter::commit()), "rawlog NAME", "content CRC" (its rawlog's,
 * contentCrcOf()). */
std::string markerValue(const std::string& dir, const std::string& key);
/** Throws std::runtime_error when the images folder `images` of `rawlog`
 * was written with a rawlog of other content: another rawlog moved or
 * copied onto its name (a backup put back over a newer run's). The same
 * rawlog compressed or not is the same; a folder reached through a link
 * is checked too (another rawlog's, whose content it notes). */
void requireRawlogOfImages(const std::string& rawlog, const std::string& images);

/** Adds to the marker of `dir` the file `name` (relative to it), before the
 * program writes it: a run killed while it fills a folder leaves a list of
 * what was its own, so what a user adds there later is told apart. */
void listOutputFile(const std::string& dir, const std::string& name);

/** Runs `write`, which fills the marked folder `dir` with files it cannot
 * list before it writes them (programs it starts name their own), then
 * lists them (listOutputFolder()), also when `write` throws. Meanwhile the
 * marker says so: a run killed in it leaves a folder all its own, which the
 * next run of the output removes whole. */
void fillListed(const std::string& dir, const std::function<void()>& write);

/** Adds to the marker of the finished folder `dir` every file in it: what
 * the program wrote, so that a file a user adds later is not replaced with it. */
void listOutputFolder(const std::string& dir);
/** A file in the marked folder `dir` (relative) that its marker does not
 * list, or "" (a marker without a list vouches for no file). An empty
 * folder counts as a file, unless its marker lists files in it (the run's,
 * emptied). */
std::string firstUnlistedIn(const std::string& dir);
/** Writes the marker into the folder `dir` (being made) naming `program`. */
void markOutputFolder(const std::string& dir, const std::string& program);

/** true when `dir` is a folder whose marker names `program`. */
bool isOutputFolderOf(const std::string& dir, const std::string& program);

/** A folder output written in a staging folder and swapped in whole. The
 * constructor clears what killed runs of `target` left (recoverLeftoversOf()),
 * checks the rule (requireOutputAllowed()) and makes a fresh staging folder
 * TARGET.staging-PID, marked as `program`'s and registered as a temporary;
 * the program writes into path(), then commit() swaps it in (replaceFolder()).
 * Destroyed without commit() or keep(), the staging folder is removed. */
class StagedFolder
{
   public:
	StagedFolder(const std::string& target, const std::string& program, const std::vector<std::string>& inputs,
				 bool force);
	~StagedFolder();
	StagedFolder(const StagedFolder&) = delete;
	StagedFolder& operator=(const StagedFolder&) = delete;

	const std::string& path() const { return staging_; }
	/** The output folder ("." or ".." by the folder's own name). */
	const std::string& target() const { return target_; }
	/** Runs `write`, which fills the staging folder; an error it throws names
	 * the output the user asked for, not the staging folder (which is removed). */
	void fill(const std::function<void()>& write) const;
	/** Checks the rule again (the folder may have been made, filled or
	 * replaced while the run went), then swaps the staging folder in. */
	void commit();
	/** Leaves the staging folder as it is (a failed run's output, for a look). */
	void keep();

   private:
	std::string target_, staging_, program_;
	std::vector<std::string> inputs_;
	bool force_{false}, done_{false};
};

/** A folder an output replaces, moved aside (moveAside()). */
struct MovedAside
{
	std::string path;  ///< TARGET.old-PID
	/** It was a folder of ours, noted "aside PID" in its marker just before the
	 * rename: only such a folder, found still so, is removed as ours. */
	bool noted{false};
	/** Given with --force: a folder of no marker is replaced whatever it holds
	 * (and kept, renamed, if it holds anything). */
	bool forced{false};
	/** Moved straight to the name it is kept under (TARGET.replaced-PID): a
	 * folder of no marker that --force replaces, which no run removes. */
	bool kept{false};
};

/** Renames `target` to TARGET.old-PID; a folder of ours first notes in its
 * marker that this run moved it ("aside PID"), so that recoverLeftoversOf()
 * can tell it from a user's backup of that name. A folder of no marker that
 * holds anything is refused unless `force`: the rule let only an empty one
 * be replaced, so it was made or filled while the run went. */
MovedAside moveAside(const std::string& target, bool force);

/** Puts the finished folder `fresh` in the place of `target`: the old
 * `target` (if any) goes aside as TARGET.old-PID, `fresh` is renamed in,
 * then the old one is removed. If the rename fails, the old is put back and
 * the error names both. All-or-nothing for a multi-file output. */
void replaceFolder(const std::string& target, const std::string& fresh, bool force);

/** Removes `old`, what an output replaced (TARGET.old-PID). What cannot be
 * removed is renamed TARGET.replaced-PID (no reader takes it for a half
 * replaced output) and warned about with the system's reason; the new
 * output is in place by then, so the run does not fail. A folder noted as
 * ours that no longer says so, or holds what its marker does not list, and
 * a folder of no marker that holds anything (replaced with --force, or
 * filled after the run found it empty) are the user's: they are kept so, and
 * said. */
void removeReplaced(const MovedAside& old);

/** TARGET.old-PID that a run, now gone, moved aside and did not finish
 * replacing (moveAside()): `target` may be that run's new folder beside an
 * old file it belongs with; or FOLDER.old-PID of a missing folder `target`
 * is in (a report killed between its two renames); "" if there is none. */
std::string halfReplaced(const std::string& target);

/** What killed runs of the output `target` left beside it, as names with a
 * process id (TARGET.staging-PID, TARGET.tmp-PID, TARGET.old-PID) whose
 * process is gone: staging and temporary copies are removed; an old copy
 * is put back when `target` is missing (the run died between the two
 * renames), else removed. Only what is ours: a folder holding the marker
 * (naming `program`, when given), or a file of `kind` (or empty) that
 * begins as `begins_with` or is cut short within it (a text output: any
 * text would be of its kind); an old copy only if its marker says that run
 * moved it aside (moveAside()); a user's file or backup with such a name
 * stays. Called before a run makes anything for `target`: names with its
 * own PID are an earlier run's. An empty folder of such a name goes too (a
 * run killed removing it). */
void recoverLeftoversOf(const std::string& target, OutputKind kind = OutputKind::Folder,
						const std::string& program = "", const std::string& begins_with = "");

}  // namespace omnirange
