// Output files: atomic writes and TSV tables (figure scripts are text made by
// the *_report headers; running gnuplot belongs to the apps, src/cli/gnuplot.hpp).
// No printing here; failures are exceptions (stickslip::Error).
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace stickslip {

/// When a write reaches the disk.
enum class Durability {
  kSynced,    ///< the file is fsynced before the rename (one journal commit per file)
  kDeferred,  ///< no fsync: the caller syncs a whole set at once (SyncFiles, cli::OutputSet)
};

/// Writes `content` to a new file in the directory of `path`, then renames it
/// over `path`: readers see the old file or the whole new one, never a part.
/// On failure the temporary file is removed and Error is thrown, naming the
/// path and the reason (errno text); `path` is then unchanged. kSynced does not
/// sync the directory: the rename is durable once the directory is fsynced.
void WriteFileAtomically(const std::string& path, const std::string& content,
                         Durability durability = Durability::kSynced);

/// Puts the data of every file in `paths` on disk: writeback is started on all
/// of them first, then each is fsynced, so a journalling file system commits
/// them together (one ext4 journal commit, not one per file). Error names the
/// file and the reason.
void SyncFiles(const std::vector<std::string>& paths);

/// A number as text: the shortest form that reads back to the same double
/// ("0.25", "1e-05", "-3.0000000000000004"); "nan", "inf", "-inf" otherwise
/// (for messages: a table refuses them, TsvTable::AddRow).
std::string FormatNumber(double x);

/// An extra column of a table, one value per row (NaN where it does not apply:
/// an empty cell in the file, TsvTable::Cell::OrEmpty).
struct ExtraColumn {
  std::string name;
  std::vector<double> values;
};

/// A tab-separated table that describes itself. Layout:
///   # key: value                metadata (AddMeta / AddComment lines), in order
///   col1<TAB>col2<TAB>...       the header line, without '#'
///   1.5<TAB>0.25<TAB>...        one line per row
/// pandas.read_csv(path, sep='\t', comment='#') and csv.DictReader (after
/// dropping the '#' lines) read the header as the column names; gnuplot reads
/// it with `set datafile columnheaders` ('#' lines are comments).
class TsvTable {
 public:
  /// Throws InvalidArgument if there are no columns or a name is empty or
  /// contains a tab or newline.
  explicit TsvTable(std::vector<std::string> columns);

  /// One cell: a number (formatted by FormatNumber) or text without tabs or
  /// newlines. A value that does not apply is an empty cell (Cell("")), never
  /// nan: AddRow refuses a number that is not finite.
  class Cell {
   public:
    Cell(double x) : text_(FormatNumber(x)), finite_(std::isfinite(x)) {}  // NOLINT: implicit
    /// x, or an empty cell where x is NaN (the library's "does not apply");
    /// an infinite x stays a number that AddRow refuses.
    static Cell OrEmpty(double x) { return std::isnan(x) ? Cell("") : Cell(x); }
    Cell(int x) : text_(std::to_string(x)) {}                 // NOLINT
    Cell(long x) : text_(std::to_string(x)) {}                // NOLINT
    Cell(unsigned long x) : text_(std::to_string(x)) {}       // NOLINT
    Cell(const char* s) : text_(s), is_text_(true) {}         // NOLINT
    Cell(const std::string& s) : text_(s), is_text_(true) {}  // NOLINT
    const std::string& text() const { return text_; }
    bool is_text() const { return is_text_; }
    /// False for a number that is nan or inf.
    bool finite() const { return finite_; }

   private:
    std::string text_;
    bool is_text_ = false;
    bool finite_ = true;
  };

  /// A "# text" line before the header. Throws InvalidArgument if the text
  /// has a line break.
  void AddComment(const std::string& text);
  /// A "# key: value" metadata line. Throws InvalidArgument if the key is
  /// empty or has a colon, or either has a line break.
  void AddMeta(const std::string& key, const std::string& value);
  /// The same lines, placed before every line added so far.
  void PrependMeta(const std::vector<std::pair<std::string, std::string>>& lines);
  /// Throws InvalidArgument if the cell count differs from the column count,
  /// a text cell has a tab or newline, or a number is nan or inf (naming the
  /// column and row); the table is then unchanged.
  void AddRow(const std::vector<Cell>& cells);
  /// Room for n more rows of about `bytes_per_row` characters (no copies of a
  /// long table's text as it grows).
  void Reserve(std::size_t n, std::size_t bytes_per_row) {
    body_.reserve(body_.size() + n * bytes_per_row);
  }

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t rows() const { return rows_; }
  /// The whole table as text, ending with a newline.
  std::string str() const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::string> comments_;
  std::string body_;
  std::size_t rows_ = 0;
};

}  // namespace stickslip
