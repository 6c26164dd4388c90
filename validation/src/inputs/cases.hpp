// Cases and the case-file format `gjk-cases/1` (docs/case-files.md, "Case files").
#pragma once

#include "common/common.hpp"
#include "common/json_text.hpp"

#include <gjk2d/exact.hpp>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace gjkval
{

// One shape of a case as given: field for field exact::Shape (gjk2d/exact.hpp states what each
// field means: the convex hull of `points` mapped by x' = c*x - s*y + px, y' = s*x + c*y + py,
// grown by `radius`). Not the same type, because the points differ: here std::array<double, 2>
// (P2), which the runner's geometry (geometry.hpp), the generators and the conversions to
// gjk::Polygon index as p[0], p[1]; there exact::Point {x, y}, exact/ being independent of
// validation/ and gjk/. toExact (below) is the one translation, and cases.cpp checks that the two
// keep the same fields.
struct ShapeIn
{
    std::vector<std::array<double, 2>> points;
    double radius = 0;
    double px = 0, py = 0;
    double c = 1, s = 0;
};

struct Case
{
    std::string name;
    ShapeIn a, b;
    // Optional provenance (docs/case-files.md, "Case files"): where the case comes from (a URL or
    // a citation) and what it is. Empty when the file gives none; never read by an evaluation.
    std::string source, comment;
};

// One entry of a case file in file order: a valid case, or a rejected one (reason non-empty).
struct CaseEntry
{
    Case c;               // as far as it could be read; c.name may be empty
    std::string label;    // "file.json#3 (case 'x')": how reports name this entry
    std::string rejected; // empty: valid
};

struct CaseFile
{
    std::string path;
    std::vector<std::string> comments;
    std::vector<CaseEntry> entries;
};

inline constexpr const char* kCaseFormat = "gjk-cases/1";

// Limits of the reader (docs/case-files.md, "Case files"): what a hostile file can cost in memory
// is bounded by these, not by what the file claims, nor by its size: a file of any number of cases
// is read as a stream. JSON beyond them is refused, cases beyond them are rejected.
inline constexpr std::size_t kMaxJsonDepth = 64;          // a case file needs 6 levels
inline constexpr std::size_t kMaxComments = 10'000;       // entries of "comments"
inline constexpr std::size_t kMaxCommentBytes = 64 << 10; // one comment, a case's source or comment
inline constexpr std::size_t kMaxCaseNameBytes = 256;     // one case name
inline constexpr std::size_t kMaxShapePoints = 1'000'000; // points of one shape
inline constexpr std::size_t kMaxCaseJsonValues = 8'000'000; // JSON values of one case

// Reads and checks a case file. A file that is unreadable, not a regular file or a pipe, not JSON
// (also: nested deeper than kMaxJsonDepth, a duplicate key, a number that overflows a double or is
// not 0 but rounds to 0) or not gjk-cases/1 throws InputError naming the file (and line:column
// where the JSON is at fault). A case with an invalid field is kept as a rejected entry naming
// file, case and field; the other cases are valid. Every string the reader returns (names,
// labels, comments, reasons) is valid UTF-8; user strings in messages and labels are quoted
// through excerpt().
CaseFile readCaseFile(const std::string& path);
CaseFile parseCaseFile(const std::string& text, const std::string& sourceName);

// The same reader as a stream: each entry goes to `consume` in file order as soon as it is read,
// and only the current case's JSON and the names seen (duplicates are rejected; NameSet,
// case_fields.hpp) are kept, so that memory hardly grows with the file. A regular file or a pipe
// is read as it is parsed. Throws InputError as readCaseFile, possibly after some entries were
// consumed (a file that is not JSON at its end).
struct CaseFileSummary
{
    std::vector<std::string> comments;
    std::size_t entries = 0;
};
CaseFileSummary streamCaseFile(const std::string& path,
                               const std::function<void(CaseEntry&&)>& consume);
// The same, reading `readPath` (a PipeCopy's) but naming `sourceName` in messages and labels.
CaseFileSummary streamCaseFile(const std::string& readPath, const std::string& sourceName,
                               const std::function<void(CaseEntry&&)>& consume);

// A pipe read once and kept for more reads: its bytes copied, as they arrive, into an unnamed
// temporary file (in TMPDIR, else /tmp) that lasts as long as this object, so that a campaign
// can check a piped case file and then stream it without holding it in memory. InputError when
// the pipe cannot be read, OutputError when the copy cannot be written.
class PipeCopy
{
  public:
    explicit PipeCopy(const std::string& pipe);
    ~PipeCopy();
    PipeCopy(const PipeCopy&) = delete;
    PipeCopy& operator=(const PipeCopy&) = delete;
    const std::string& path() const { return path_; } // /proc/self/fd/N: readable, not listed

  private:
    int fd_ = -1;
    std::string path_;
};

// Writes a gjk-cases/1 file: one case per line, numbers in shortest round-trip form.
std::string caseFileText(const std::vector<std::string>& comments, const std::vector<Case>& cases);
void writeCaseFile(const std::string& path, const std::vector<std::string>& comments,
                   const std::vector<Case>& cases);
Json caseToJson(const Case& c);
Json shapeToJson(const ShapeIn& s);

// A JSON file (a shard's state, a checkpoint), parsed; InputError "who: PATH: cannot open: ..." or
// "who: PATH:LINE:COLUMN: not JSON".
Json readJsonFile(const std::string& path, const std::string& who);

// The exact side's view of a shape; roundToFloat rounds every input double to float first (the
// input the float variants actually see).
// double(float(v)), the value a float variant receives. Deliberately not inline: GCC 12.2's SLP
// vectorizer folds two adjacent double -> float -> double round trips (a point's x and y) into the
// identity at -O2 and -O3, so `p = {double(float(p[0])), double(float(p[1]))}` silently kept the
// doubles (reproduced by the test "float rounding of a case for the float variants' truth").
// A call per value keeps the vectorizer out.
[[gnu::noinline]] double roundToFloat(double v);
// Every number of the shape rounded to float (what the float variants receive), as doubles.
ShapeIn roundedToFloat(const ShapeIn& s);
exact::Shape toExact(const ShapeIn& s, bool roundToFloat = false);
// True when every number of the case is finite after rounding to float, and no rotation rounds to
// (0, 0).
bool representableInFloat(const Case& c);

} // namespace gjkval
