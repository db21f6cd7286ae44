#pragma once
// Binary archive of a simulation's dynamic state, for checkpoints (docs/design.md §4.8). Each
// stateful part writes its section behind a four-letter tag and reads it back in the same
// order; the reader checks every tag and every length, so a checkpoint of another layout or a
// truncated one is refused with a reason instead of restoring garbage. Values are stored in the
// machine's byte order, bit for bit (a restored double is the same double).
//
// Writer and reader share one interface, so a part describes its state once, in a template
// run with either (`serialize(self, archive)`: `archive.tag("NAME"); archive(member); ...`),
// and its save and load cannot disagree on the order: `archive(x)` writes x or reads into it,
// `archive.count(v, limit)` writes v's size or reads one (at most `limit`) and resizes v.
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/types.hpp"

namespace wirepack {

// A checkpoint that cannot be restored (wrong layout, truncated, another scene).
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StateWriter {
 public:
  static constexpr bool kLoading = false;
  // Each value in turn, left to right.
  template <class... T>
  void operator()(const T&... v) {
    (put(v), ...);
  }
  template <class V>
  void count(const V& v, std::uint64_t /*limit*/) {
    put(static_cast<std::uint64_t>(v.size()));
  }
  // A section's start: four letters the reader expects at the same place.
  void tag(const char (&t)[5]) { raw(t, 4); }
  template <class T>
  requires std::is_arithmetic_v<T>
  void put(T v) { raw(&v, sizeof v); }
  void put(const Vec3& p) { raw(p.data(), 3 * sizeof(double)); }
  void put(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    raw(s.data(), s.size());
  }
  // Vectors of plain values (numbers, arrays and structs of numbers).
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void put(const std::vector<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    raw(v.data(), v.size() * sizeof(T));
  }
  void put(const Vec3List& v) {
    put(static_cast<std::uint64_t>(v.size()));
    for (const Vec3& p : v) raw(p.data(), 3 * sizeof(double));
  }
  void put(const std::vector<std::pair<int, int>>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    for (const auto& [a, b] : v) {
      put(a);
      put(b);
    }
  }
  void put(const std::vector<std::vector<int>>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    for (const auto& row : v) put(row);
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw CheckpointError("checkpoint state: " + why);
  }
  const std::string& bytes() const { return buf_; }
  std::string take() { return std::move(buf_); }

 private:
  void raw(const void* p, std::size_t n) { buf_.append(static_cast<const char*>(p), n); }
  std::string buf_;
};

class StateReader {
 public:
  static constexpr bool kLoading = true;
  explicit StateReader(std::string_view bytes) : buf_(bytes) {}
  template <class... T>
  void operator()(T&... v) {
    (get(v), ...);
  }
  template <class V>
  void count(V& v, std::uint64_t limit) {
    const auto n = get<std::uint64_t>();
    if (n > limit) fail(std::to_string(n) + " elements, at most " + std::to_string(limit));
    v.resize(static_cast<std::size_t>(n));
  }
  void tag(const char (&t)[5]) {
    char got[4];
    raw(got, 4);
    if (std::memcmp(got, t, 4) != 0)
      fail("expected section '" + std::string(t) + "', found '" + std::string(got, 4) + "'");
  }
  template <class T>
  requires std::is_arithmetic_v<T>
  void get(T& v) { raw(&v, sizeof v); }
  template <class T>
  requires std::is_arithmetic_v<T> T get() {
    T v{};
    get(v);
    return v;
  }
  void get(Vec3& p) { raw(p.data(), 3 * sizeof(double)); }
  void get(std::string& s) {
    s.resize(length(1));
    raw(s.data(), s.size());
  }
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void get(std::vector<T>& v) {
    v.resize(length(sizeof(T)));
    raw(v.data(), v.size() * sizeof(T));
  }
  void get(Vec3List& v) {
    v.resize(length(3 * sizeof(double)));
    for (Vec3& p : v) raw(p.data(), 3 * sizeof(double));
  }
  void get(std::vector<std::pair<int, int>>& v) {
    v.resize(length(2 * sizeof(int)));
    for (auto& [a, b] : v) {
      get(a);
      get(b);
    }
  }
  void get(std::vector<std::vector<int>>& v) {
    v.resize(length(sizeof(std::uint64_t)));
    for (auto& row : v) get(row);
  }
  // Throws unless every byte was read.
  void expect_end() const {
    if (pos_ != buf_.size()) fail(std::to_string(buf_.size() - pos_) + " bytes left over");
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw CheckpointError("checkpoint state at byte " + std::to_string(pos_) + ": " + why);
  }

 private:
  // A stored element count, checked against the bytes left (each element >= `unit` bytes).
  std::size_t length(std::size_t unit) {
    const auto n = get<std::uint64_t>();
    if (unit > 0 && n > (buf_.size() - pos_) / unit)
      fail("length " + std::to_string(n) + " too long");
    return static_cast<std::size_t>(n);
  }
  void raw(void* p, std::size_t n) {
    if (n > buf_.size() - pos_) fail("truncated");
    if (n > 0) std::memcpy(p, buf_.data() + pos_, n);
    pos_ += n;
  }
  std::string_view buf_;
  std::size_t pos_ = 0;
};

}  // namespace wirepack
