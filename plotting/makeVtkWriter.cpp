//--------------------------------------------------------------------------
// makeVtkWriter — the text of a legacy VTK file, ASCII or BINARY
//--------------------------------------------------------------------------
// See makeVtkWriter.h for the format, inputs and outputs.
//--------------------------------------------------------------------------
#include "makeVtkWriter.h"
#include <cstdint>
#include <cstring>
#include <sstream>

namespace ample {

VtkWriter::VtkWriter(VtkFormat format, const std::string& title, const std::string& dataset)
    : format_(format) {
  out_ = "# vtk DataFile Version 2.0\n" + title + "\n" +
         (format == VtkFormat::Binary ? "BINARY\n" : "ASCII\n") + "DATASET " + dataset + "\n";
}

const char* VtkWriter::realType() const { return format_ == VtkFormat::Binary ? "float" : "double"; }

void VtkWriter::line(const std::string& text) { out_ += text + "\n"; }

void VtkWriter::bigEndian32(unsigned int bits) {
  for (int shift = 24; shift >= 0; shift -= 8) out_ += char((bits >> shift) & 0xffu);
}

void VtkWriter::reals(const std::vector<double>& v, int perLine) {
  if (format_ == VtkFormat::Binary) {
    out_.reserve(out_.size() + 4 * v.size() + 1);
    for (double x : v) {
      const float f = float(x);                 // IEEE-754 single, rounded to nearest
      std::uint32_t bits;
      std::memcpy(&bits, &f, 4);
      bigEndian32(bits);
    }
    out_ += "\n";
    return;
  }
  std::ostringstream s;
  s.precision(15);
  for (size_t k = 0; k < v.size(); ++k) s << v[k] << ((k + 1) % size_t(perLine) == 0 ? "\n" : " ");
  out_ += s.str();
}

void VtkWriter::ints(const std::vector<int>& v, int perLine) {
  if (format_ == VtkFormat::Binary) {
    out_.reserve(out_.size() + 4 * v.size() + 1);
    for (int i : v) bigEndian32(std::uint32_t(i));  // two's complement, as int32
    out_ += "\n";
    return;
  }
  std::ostringstream s;
  for (size_t k = 0; k < v.size(); ++k) s << v[k] << ((k + 1) % size_t(perLine) == 0 ? "\n" : " ");
  out_ += s.str();
}

}  // namespace ample
