//--------------------------------------------------------------------------
// makeVtkWriter — the text of a legacy VTK file, ASCII or BINARY
//--------------------------------------------------------------------------
// See makeVtkWriter.h for the format, inputs and outputs.
//--------------------------------------------------------------------------
#include "makeVtkWriter.h"
#include "ample/errors.h"
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace ample {

// x as printf "%.15g" writes it, into buf (32 bytes); the end of the text. std::to_chars where
// the C++ library has it for doubles (__cpp_lib_to_chars: GCC's), else snprintf itself
// (emscripten's libc++ 13, the browser build: the same text, only slower)
static char* real15(char* buf, double x) {
#if defined(__cpp_lib_to_chars)
  return std::to_chars(buf, buf + 32, x, std::chars_format::general, 15).ptr;
#else
  return buf + std::snprintf(buf, 32, "%.15g", x);
#endif
}

VtkWriter::VtkWriter(VtkFormat format, const std::string& title, const std::string& dataset,
                     const std::string& path, size_t chunkBytes)
    : format_(format), path_(path), chunk_(chunkBytes) {
  if (!path_.empty() && !(file_ = std::fopen((path_ + ".tmp").c_str(), "wb")))
    throw RunError("cannot write " + path_ + ".tmp");
  if (file_) out_.reserve(chunk_ + 64);                  // a chunk and one number more
  out_ += "# vtk DataFile Version 2.0\n" + title + "\n" +
          (format == VtkFormat::Binary ? "BINARY\n" : "ASCII\n") + "DATASET " + dataset + "\n";
}

VtkWriter::~VtkWriter() {
  if (!file_) return;                                    // finished, or kept in memory
  std::fclose(file_);
  std::remove((path_ + ".tmp").c_str());
}

const char* VtkWriter::realType() const { return format_ == VtkFormat::Binary ? "float" : "double"; }

void VtkWriter::line(const std::string& text) {
  out_ += text;
  out_ += '\n';
  flushIfFull();
}

void VtkWriter::flushIfFull() {
  if (!file_ || out_.size() < chunk_) return;
  if (std::fwrite(out_.data(), 1, out_.size(), file_) != out_.size())
    throw RunError("cannot write " + path_ + ".tmp");
  out_.clear();                                          // keeps its capacity
}

void VtkWriter::finish() {
  const bool written = std::fwrite(out_.data(), 1, out_.size(), file_) == out_.size();
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  out_.clear();
  if (!written || !closed) {
    std::remove((path_ + ".tmp").c_str());
    throw RunError("cannot write " + path_ + ".tmp");
  }
  if (std::rename((path_ + ".tmp").c_str(), path_.c_str()) != 0) throw RunError("cannot rename " + path_ + ".tmp");
}

void VtkWriter::bigEndian32(unsigned int bits) {
  for (int shift = 24; shift >= 0; shift -= 8) out_ += char((bits >> shift) & 0xffu);
}

void VtkWriter::separator(size_t k, int perLine) { out_ += (k + 1) % size_t(perLine) == 0 ? '\n' : ' '; }

std::string vtkReal(double x) {
  char buf[32];                                          // "-1.23456789012345e-308" fits
  return std::string(buf, real15(buf, x));
}

void VtkWriter::reals(const std::vector<double>& v, int perLine) {
  char buf[32];
  for (size_t k = 0; k < v.size(); ++k) {
    if (format_ == VtkFormat::Binary) {
      const float f = float(v[k]);                       // IEEE-754 single, rounded to nearest
      std::uint32_t bits;
      std::memcpy(&bits, &f, 4);
      bigEndian32(bits);
    } else {
      out_.append(buf, real15(buf, v[k]));
      separator(k, perLine);
    }
    flushIfFull();
  }
  if (format_ == VtkFormat::Binary) out_ += '\n';
}

void VtkWriter::ints(const std::vector<int>& v, int perLine) {
  char buf[16];
  for (size_t k = 0; k < v.size(); ++k) {
    if (format_ == VtkFormat::Binary) {
      bigEndian32(std::uint32_t(v[k]));                  // two's complement, as int32
    } else {
      out_.append(buf, std::to_chars(buf, buf + sizeof buf, v[k]).ptr);
      separator(k, perLine);
    }
    flushIfFull();
  }
  if (format_ == VtkFormat::Binary) out_ += '\n';
}

}  // namespace ample
