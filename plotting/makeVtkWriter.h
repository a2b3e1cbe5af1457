//--------------------------------------------------------------------------
// makeVtkWriter — the text of a legacy VTK file, ASCII or BINARY
//--------------------------------------------------------------------------
// The legacy format (VTK file formats, "Simple Legacy Formats", version 2.0):
// four header lines (the version line, a title, ASCII or BINARY, the DATASET
// line), then sections, each a keyword line in ASCII followed by its numbers.
//   ASCII:  reals as decimal text with 15 significant digits (type "double"),
//           ints as decimal text, perLine numbers to a line.
//   BINARY: the numbers as raw big-endian 4-byte values, reals as IEEE-754
//           single precision (type "float"), ints as 32-bit two's complement,
//           with nothing between them and one "\n" after the block (so the
//           next keyword starts a line). A block of k numbers is 4 k + 1 bytes.
// The keyword lines are the same in both formats except for the type name,
// which a section gets from realType(). makeVtk and makeVtkMP build their files
// with it; the choice comes from `--vtk-format` (cli.cpp, RunOptions).
// Inputs:  format · the lines and blocks of numbers, in file order
// Outputs: text() — the whole file, for atomicWrite
// Tests:   tests/test_output.cpp (binary read back against the ASCII file)
//--------------------------------------------------------------------------
#pragma once
#include <string>
#include <vector>

namespace ample {

enum class VtkFormat { Ascii, Binary };

class VtkWriter {
 public:
  // writes the four header lines; dataset is e.g. "UNSTRUCTURED_GRID"
  VtkWriter(VtkFormat format, const std::string& title, const std::string& dataset);
  const char* realType() const;                           // "double" or "float"
  void line(const std::string& text);                     // one keyword line, "\n" added
  void reals(const std::vector<double>& v, int perLine);  // a block of reals
  void ints(const std::vector<int>& v, int perLine);      // a block of ints
  const std::string& text() const { return out_; }

 private:
  void bigEndian32(unsigned int bits);                    // 4 bytes, most significant first
  VtkFormat format_;
  std::string out_;
};

}  // namespace ample
