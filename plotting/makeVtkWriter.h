//--------------------------------------------------------------------------
// makeVtkWriter — the text of a legacy VTK file, ASCII or BINARY
//--------------------------------------------------------------------------
// The legacy format (VTK file formats, "Simple Legacy Formats", version 2.0):
// four header lines (the version line, a title, ASCII or BINARY, the DATASET
// line), then sections, each a keyword line in ASCII followed by its numbers.
//   ASCII:  reals as decimal text with 15 significant digits (type "double";
//           std::to_chars, general format: the same text as printf "%.15g";
//           printf itself where the C++ library lacks to_chars for doubles),
//           ints as decimal text, perLine numbers to a line.
//   BINARY: the numbers as raw big-endian 4-byte values, reals as IEEE-754
//           single precision (type "float"), ints as 32-bit two's complement,
//           with nothing between them and one "\n" after the block (so the
//           next keyword starts a line). A block of k numbers is 4 k + 1 bytes.
// The keyword lines are the same in both formats except for the type name,
// which a section gets from realType(). makeVtk and makeVtkMP build their files
// with it; the choice comes from `--vtk-format` (cli.cpp, RunOptions).
// Given a path, the text goes through one buffer into path.tmp, flushed every
// chunkBytes (1 MiB; a file of a million points never sits whole in memory),
// and finish() renames path.tmp to path, so a file at path is always complete
// (an unfinished writer removes path.tmp). Without a path the text stays in
// memory for text() (the tests read it).
// Inputs:  format · the lines and blocks of numbers, in file order · path
// Outputs: the file at path after finish(), or text()
// Tests:   tests/test_output.cpp (binary read back against the ASCII file,
//          reals against printf "%.15g", chunked file against the whole text)
//--------------------------------------------------------------------------
#pragma once
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace ample {

enum class VtkFormat { Ascii, Binary };

class VtkWriter {
 public:
  // writes the four header lines; dataset is e.g. "UNSTRUCTURED_GRID";
  // path "" keeps the text in memory, else it goes to path.tmp chunk by chunk
  VtkWriter(VtkFormat format, const std::string& title, const std::string& dataset,
            const std::string& path = "", size_t chunkBytes = size_t(1) << 20);
  ~VtkWriter();                                           // unfinished: path.tmp removed
  VtkWriter(const VtkWriter&) = delete;
  VtkWriter& operator=(const VtkWriter&) = delete;
  const char* realType() const;                           // "double" or "float"
  void line(const std::string& text);                     // one keyword line, "\n" added
  void reals(const std::vector<double>& v, int perLine);  // a block of reals
  void ints(const std::vector<int>& v, int perLine);      // a block of ints
  void finish();                                          // last chunk, close, rename to path
  const std::string& text() const { return out_; }        // without a path: the whole file

 private:
  void bigEndian32(unsigned int bits);                    // 4 bytes, most significant first
  void separator(size_t k, int perLine);                  // " " or "\n" after number k
  void flushIfFull();                                     // a full buffer goes to path.tmp
  VtkFormat format_;
  std::string path_;
  size_t chunk_;
  std::FILE* file_ = nullptr;
  std::string out_;                                       // the text not yet written
};

// x as the ASCII format writes it: 15 significant digits, "%.15g"
std::string vtkReal(double x);

}  // namespace ample
