#pragma once
/// @file random.hpp
/// Seeded random streams. There is no global generator: every stream is derived from the
/// run seed and a stream name, so adding a stream never shifts another one.

#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <string_view>

namespace fsweep {
inline namespace core {

/// The engine's generator. std::mt19937_64 is specified bit-for-bit by the standard.
using Rng = std::mt19937_64;

/// SplitMix64 finaliser: a bijective 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31U);
}

/// FNV-1a's 64-bit offset basis: the hash of the empty string.
inline constexpr std::uint64_t kFnv1aBasis = 0xCBF29CE484222325ULL;

/// FNV-1a hash of a string (64 bit), stable across platforms. `h` continues a hash: the hash of
/// a + b is fnv1a(b, fnv1a(a)).
constexpr std::uint64_t fnv1a(std::string_view s, std::uint64_t h = kFnv1aBasis) {
  for (const char c : s) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001B3ULL;
  }
  return h;
}

/// `v` as 16 lower-case hex digits (run keys, sweep hashes, journal fields).
inline std::string hex64(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

/// Seed of the stream `name` of a run with seed `seed`.
constexpr std::uint64_t derive_seed(std::uint64_t seed, std::string_view name) {
  return mix64(seed ^ mix64(fnv1a(name)));
}

/// A generator for stream `name` of run seed `seed`.
inline Rng make_rng(std::uint64_t seed, std::string_view name) { return Rng(derive_seed(seed, name)); }

/// Uniform double in [0, 1) from 53 random bits. (std::uniform_real_distribution is not
/// specified bit-for-bit across standard libraries; this is.)
inline double uniform01(Rng& rng) { return static_cast<double>(rng() >> 11U) * 0x1.0p-53; }

/// Uniform integer in [0, n), n > 0, by rejection (unbiased, platform independent).
inline std::uint64_t uniform_below(Rng& rng, std::uint64_t n) {
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
  std::uint64_t r = rng();
  while (r >= limit) r = rng();
  return r % n;
}

}  // namespace core
}  // namespace fsweep
