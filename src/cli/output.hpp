// One run's output files, written as a set: checked before the run, staged
// in a private directory, figures verified, then renamed into place together.
//
// Promises (docs/reliability.md):
// - Up front (UsageError, exit 2, nothing created): the destination directory
//   exists or its parent does, and is writable; no control character in any
//   path; every name fits NAME_MAX and PATH_MAX with its temporary suffix; at each file's place
//   there is nothing or a regular file. A symbolic link, directory, device, FIFO or socket there is
//   refused: a symlink is never followed nor replaced.
// - Every file goes first into a fresh hidden directory `.<prog>-<pid>-XXXXXX`
//   inside the destination (mkdtemp: unique per run), created only when the
//   first file is written. A run killed outright (SIGKILL) leaves its staging
//   directory behind, never a file under an output's name; the next run of
//   the same app on that directory removes the staging directories whose
//   process is gone. Commit() renames the staged files into place while
//   holding an exclusive flock on the destination directory, so two runs on
//   the same directory each leave a whole set (the last to commit wins), never
//   a mix. The destructor removes whatever is still staged.
// - Durable as a set: Write() does not fsync; Commit() syncs every staged
//   file together (SyncFiles), renames them, then fsyncs the directory once.
//   After a power loss the old set stands until the renames began, the new one
//   once Commit() returned; each file is whole, old or new.
// - Draw() runs gnuplot inside the staging directory and checks every figure
//   (a whole PNG: signature and IEND chunk); a figure that fails the check is
//   a failure, and the caller keeps the old files by not committing.
// - Commit() removes what an older run of any app left under another of
//   KnownOutputNames(), so a directory never holds a mix of two runs' sets.
//
// Use (any app writing files):
//   cli::OutputSet out(dir, {"a.tsv", "a.gp", "a.png"}, "--out", "ss_x");  // before the run
//   ... compute ...
//   out.Write("a.tsv", table.str());
//   out.Write("a.gp", script);  // names inside the script are plain file names
//   const cli::GnuplotResult g = out.Draw("a.gp", {"a.png"}, cancelled);
//   if (g.status == cli::GnuplotStatus::kFailed) return 1;  // old files kept
//   out.Commit(g.ok() ? std::vector<std::string>{} : figures);  // stale ones removed
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "cli/gnuplot.hpp"

namespace stickslip::cli {

// Every file name an app of this project writes (data, scripts, and each
// figure in png, pdf and svg). OutputSet::Commit removes those an older run
// left in the directory and this one did not write (issue 35), and nothing
// else: a user's own files there stay. A new output name belongs here.
const std::vector<std::string>& KnownOutputNames();

class OutputSet {
 public:
  // dir: destination directory (made at the first Write if only it is
  // missing); names: every plain file name this run may write there;
  // source: the option that named dir, for messages; prog: the staging
  // directory's prefix. Throws UsageError as described above.
  OutputSet(std::string dir, std::vector<std::string> names, const std::string& source,
            const std::string& prog);
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  const std::string& dir() const { return dir_; }
  // Writes one of the names into the staging directory. Throws Error (with
  // the reason, e.g. "No space left on device"); nothing is left half-written.
  void Write(const std::string& name, const std::string& content);
  // The staged content of a name written before (Error if it was not).
  std::string Read(const std::string& name);
  // Runs gnuplot on the staged `script` inside the staging directory, then
  // checks each of `figures`. A figure that is missing, empty or truncated
  // makes the status kFailed, naming it. On any status but kOk the staged
  // figures are discarded.
  GnuplotResult Draw(const std::string& script, const std::vector<std::string>& figures,
                     const std::function<bool()>& cancelled);
  // Renames every staged file into dir under the lock, and removes the
  // regular files named in `stale` or in KnownOutputNames() that this run did
  // not write (figures of an older run that no longer match its data, another
  // app's or --format's files). Throws Error.
  void Commit(const std::vector<std::string>& stale = {});
  // Removes the staging directory and what is still in it (the destructor
  // does this; for a process that ends without unwinding, e.g. _Exit).
  void Discard();

 private:
  std::string Staging();  // creates dir and the staging directory on first use
  void SweepLeftovers() const;
  void CheckName(const std::string& name, const std::string& source) const;
  std::string dir_;
  std::vector<std::string> names_;
  std::vector<std::string> staged_;
  std::string prog_;
  std::string staging_;
};

}  // namespace stickslip::cli
