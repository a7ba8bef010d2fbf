// vtp_distance_matrix: a 64-bit hash, to recognise a mesh, a source list or a run's parameters.
// (Not cryptographic: it protects against mistakes, such as resuming with another mesh.)

#ifndef VTP_DISTANCE_MATRIX_HASHING_H
#define VTP_DISTANCE_MATRIX_HASHING_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace vtp_matrix {

inline std::uint64_t splitmix64(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

class Hash64
{
public:
  void add(std::uint64_t v) { m_h = splitmix64(m_h ^ splitmix64(v + m_n++)); }
  void add_double(double d)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &d, sizeof(bits));
    add(bits);
  }
  void add_bytes(const void* data, std::size_t n)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    add(n);
    for(std::size_t i = 0; i < n; i += 8)
    {
      std::uint64_t w = 0;
      std::memcpy(&w, p + i, (n - i < 8) ? n - i : 8);
      add(w);
    }
  }
  std::uint64_t value() const { return m_h; }
  std::string hex() const
  {
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(m_h));
    return text;
  }

private:
  std::uint64_t m_h = 0x5654505f676d6174ULL;
  std::uint64_t m_n = 0;
};

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_HASHING_H
