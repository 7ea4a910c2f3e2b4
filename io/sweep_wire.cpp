#include "io/sweep_wire.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace vibro {
namespace {

constexpr std::uint32_t kRecordMark = 0x52435356;  // "VSCR"

class Writer {
 public:
  explicit Writer(std::string& out) : out_(out) {}
  template <class T>
  void put(T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    out_.append(b, sizeof(T));
  }
  void put_string(const std::string& s) {
    put<std::uint32_t>(static_cast<std::uint32_t>(s.size()));
    out_.append(s);
  }

 private:
  std::string& out_;
};

// Reads what Writer wrote; throws std::out_of_range past the end.
class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}
  template <class T>
  T get() {
    if (in_.size() - at_ < sizeof(T)) throw std::out_of_range("record");
    T v;
    std::memcpy(&v, in_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::string get_string() {
    const auto n = get<std::uint32_t>();
    if (in_.size() - at_ < n) throw std::out_of_range("record");
    std::string s(in_.substr(at_, n));
    at_ += n;
    return s;
  }
  bool done() const { return at_ == in_.size(); }

 private:
  std::string_view in_;
  std::size_t at_ = 0;
};

void put_run(Writer& w, const SweepRun& r) {
  w.put(r.value);
  w.put(r.value2);
  w.put<std::int32_t>(r.start);
  w.put<std::int32_t>(r.direction);
  w.put<std::uint32_t>(static_cast<std::uint32_t>(r.points.size()));
  for (const SectionPoint& p : r.points) {
    w.put<std::int32_t>(p.pellet);
    w.put(p.t);
    w.put(p.phi);
    w.put(p.dphi);
    w.put(p.phase);
    w.put<std::int32_t>(p.limiter);
    w.put<std::uint8_t>(p.trusted);
  }
  w.put<std::int32_t>(r.period);
  w.put(r.impacts_per_period);
  w.put<std::uint8_t>(r.at_rest);
  w.put<std::uint8_t>(r.sticks);
  w.put<std::uint8_t>(r.rests);
  w.put<std::uint8_t>(r.trusted);
  w.put(r.trusted_until);
  w.put<std::int32_t>(static_cast<std::int32_t>(r.termination));
  w.put_string(r.message);
  w.put(r.error_estimate);
  w.put<std::uint8_t>(r.lyapunov.has_value());
  if (r.lyapunov) w.put(*r.lyapunov);
}

SweepRun get_run(Reader& in) {
  SweepRun r;
  r.value = in.get<double>();
  r.value2 = in.get<double>();
  r.start = in.get<std::int32_t>();
  r.direction = in.get<std::int32_t>();
  const auto points = in.get<std::uint32_t>();
  for (std::uint32_t k = 0; k < points; ++k) {
    SectionPoint p;
    p.pellet = in.get<std::int32_t>();
    p.t = in.get<double>();
    p.phi = in.get<double>();
    p.dphi = in.get<double>();
    p.phase = in.get<double>();
    p.limiter = in.get<std::int32_t>();
    p.trusted = in.get<std::uint8_t>() != 0;
    r.points.push_back(p);
  }
  r.period = in.get<std::int32_t>();
  r.impacts_per_period = in.get<double>();
  r.at_rest = in.get<std::uint8_t>() != 0;
  r.sticks = in.get<std::uint8_t>() != 0;
  r.rests = in.get<std::uint8_t>() != 0;
  r.trusted = in.get<std::uint8_t>() != 0;
  r.trusted_until = in.get<double>();
  const auto termination = in.get<std::int32_t>();
  if (termination < 0 || termination > static_cast<int>(Termination::cancelled))
    throw std::out_of_range("termination");
  r.termination = static_cast<Termination>(termination);
  r.message = in.get_string();
  r.error_estimate = in.get<double>();
  if (in.get<std::uint8_t>() != 0) r.lyapunov = in.get<double>();
  return r;
}

}  // namespace

void append_chain(std::string& bytes, const ChainRuns& chain) {
  std::string body;
  Writer w(body);
  w.put<std::int32_t>(chain.chain);
  w.put<std::uint32_t>(static_cast<std::uint32_t>(chain.runs.size()));
  for (const SweepRun& r : chain.runs) put_run(w, r);
  Writer head(bytes);
  head.put(kRecordMark);
  head.put<std::uint64_t>(body.size());
  bytes += body;
}

ReadChains read_chains(std::string_view bytes) {
  ReadChains out;
  constexpr std::size_t kHead = sizeof(std::uint32_t) + sizeof(std::uint64_t);
  while (bytes.size() - out.consumed >= kHead) {
    Reader head(bytes.substr(out.consumed, kHead));
    if (head.get<std::uint32_t>() != kRecordMark) {
      out.malformed = true;
      break;
    }
    const auto length = head.get<std::uint64_t>();
    if (bytes.size() - out.consumed - kHead < length) break;  // cut off by a crash: left out
    Reader in(bytes.substr(out.consumed + kHead, length));
    try {
      ChainRuns c;
      c.chain = in.get<std::int32_t>();
      const auto runs = in.get<std::uint32_t>();
      for (std::uint32_t k = 0; k < runs; ++k) c.runs.push_back(get_run(in));
      if (!in.done()) throw std::out_of_range("record");
      out.chains.push_back(std::move(c));
    } catch (const std::out_of_range&) {
      out.malformed = true;
      break;
    }
    out.consumed += kHead + length;
  }
  return out;
}

}  // namespace vibro
