// What the fuzz targets share: the fuzzer's bytes read as a stream of small
// values, and a check that stops the run where an invariant breaks.
#ifndef FuzzBytes_h
#define FuzzBytes_h

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace fuzz
{

// Reads the fuzzer's bytes as a stream of small values; zeros when exhausted.
class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }
  std::uint8_t byte() { return this->At < this->Size ? this->Data[this->At++] : 0; }
  double unit() // in [-1, 1]
  {
    const int value = (this->byte() << 8) | this->byte();
    return value / 32767.5 - 1.0;
  }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t At = 0;
};

// A broken invariant is a crash the fuzzer keeps, with its input.
inline void require(bool condition)
{
  if (!condition)
  {
    std::abort();
  }
}

} // namespace fuzz

#endif
