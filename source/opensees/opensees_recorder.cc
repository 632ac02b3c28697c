// OpenSees's Node and Element recorders (NodeRecorder.cpp,
// ElementRecorder.cpp, DataFileStream.cpp: values streamed with
// setprecision(p), separated by " ", one line per record), and printf's
// %.{p}g text (ISO C 7.21.6.1's g conversion; opensees_recorder.h says how
// its short path is exact).
#include <poundfe/opensees/opensees_recorder.h>
#include <poundfe/output/atomic_file.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace poundfe
{
  namespace opensees
  {
    namespace
    {
      /// The text a recorder keeps before it writes to its file.
      constexpr std::size_t flush_size = 1u << 16;

      using Wide = unsigned __int128;

      /// 5^0 to 5^27 (5^27 < 2^63).
      constexpr std::array<std::uint64_t, 28> powers_of_five = [] {
        std::array<std::uint64_t, 28> p{};
        p[0] = 1;
        for (std::size_t i = 1; i < p.size(); ++i)
          p[i] = 5 * p[i - 1];
        return p;
      }();

      /// |x| = m 2^e times 10^q = m 5^q 2^(e + q) as an integer `whole`
      /// and the comparison of its fraction with one half (-1 below, 0 a
      /// tie, 1 above), exactly in 128-bit integers; false when 10^|q| is
      /// past the table or the value past 2^64.
      bool
      scaled(const std::uint64_t m, const int e, const int q, std::uint64_t &whole, int &half)
      {
        if (q > 27 || q < -27)
          return false;
        Wide numerator = m, denominator = 1; // the value numerator / denominator
        int  shift     = e + q;              // times 2^shift
        if (q >= 0)
          numerator *= powers_of_five[q];    // < 2^116
        else
          denominator = powers_of_five[-q];
        if (q >= 0 && shift < 0) // a power of two below: shifts, not a division
          {
            const int k = -shift;
            if (k >= 127 || (numerator >> k) >> 64 != 0)
              return false;
            whole                = static_cast<std::uint64_t>(numerator >> k);
            const Wide remainder = numerator & ((Wide(1) << k) - 1), one_half = Wide(1) << (k - 1);
            half = remainder < one_half ? -1 : remainder == one_half ? 0 : 1;
            return true;
          }
        if (shift > 0)
          {
            if (shift > 60 || (numerator >> (127 - shift)) != 0)
              return false;
            numerator <<= shift;
          }
        else if (shift < 0)
          {
            if (-shift > 64 || (denominator >> (127 + shift)) != 0)
              return false;
            denominator <<= -shift;
          }
        const Wide quotient = numerator / denominator;
        if (quotient >> 64 != 0)
          return false;
        whole                = static_cast<std::uint64_t>(quotient);
        const Wide remainder = numerator - quotient * denominator;
        half = 2 * remainder < denominator ? -1 : 2 * remainder == denominator ? 0 : 1;
        return true;
      }

      /// The p digits of |x| rounded and its decimal exponent, or false
      /// where the short path leaves it to std::to_chars (a tie, a
      /// subnormal, a power of ten past the table).
      bool
      rounded_digits(const double magnitude, const int p, std::uint64_t &digits, int &exponent)
      {
        std::uint64_t bits;
        std::memcpy(&bits, &magnitude, sizeof bits);
        const int biased = static_cast<int>(bits >> 52);
        if (biased == 0)
          return false; // subnormal
        const std::uint64_t m = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1) << 52);
        const int           e = biased - 1075; // |x| = m 2^e
        // floor(log10 |x|) from the binary exponent: exact or one too small
        exponent         = ((biased - 1023) * 78913) >> 18;
        const auto lower = std::uint64_t(1) * powers_of_five[p - 1] << (p - 1); // 10^(p-1)
        const auto upper = lower * 10;
        int        half  = 0;
        if (!scaled(m, e, p - 1 - exponent, digits, half))
          return false;
        if (digits >= upper && !scaled(m, e, p - 1 - ++exponent, digits, half))
          return false;
        if (digits < lower || digits >= upper || half == 0)
          return false; // the estimate off by more, or a tie (to_chars rounds those)
        if (half > 0 && ++digits == upper)
          {
            digits = lower;
            ++exponent;
          }
        return true;
      }

      /// "00" to "99".
      constexpr std::array<char, 200> digit_pairs = [] {
        std::array<char, 200> pairs{};
        for (int i = 0; i < 100; ++i)
          {
            pairs[2 * i]     = static_cast<char>('0' + i / 10);
            pairs[2 * i + 1] = static_cast<char>('0' + i % 10);
          }
        return pairs;
      }();

      /// The n decimal digits of `value` (< 10^n, n <= 9, leading zeros
      /// kept) at text[0, n), two at a time from the last.
      void
      write_small_digits(char *text, int n, std::uint32_t value)
      {
        for (; n >= 2; n -= 2, value /= 100)
          std::memcpy(text + n - 2, &digit_pairs[2 * (value % 100)], 2);
        if (n == 1)
          text[0] = static_cast<char>('0' + value);
      }

      /// The same for n <= 17: the last eight digits and the others apart,
      /// each in 32-bit arithmetic.
      void
      write_digits(char *text, const int n, const std::uint64_t value)
      {
        if (n <= 9)
          return write_small_digits(text, n, static_cast<std::uint32_t>(value));
        write_small_digits(text, n - 8, static_cast<std::uint32_t>(value / 100000000));
        write_small_digits(text + n - 8, 8, static_cast<std::uint32_t>(value % 100000000));
      }

      /// printf's exponent: its sign and two digits at least.
      char *
      write_exponent(char *out, const int exponent)
      {
        *out++      = 'e';
        *out++      = exponent < 0 ? '-' : '+';
        const int e = exponent < 0 ? -exponent : exponent;
        if (e < 10)
          *out++ = '0';
        return std::to_chars(out, out + 3, e).ptr;
      }
    } // namespace

    char *
    write_precision_text(char *out, const double x, int precision)
    {
      if (precision == 0)
        precision = 1; // C's rule for %g
      if (x == 0) // zeros are most of a gap's open steps
        {
          if (std::signbit(x))
            *out++ = '-';
          *out++ = '0';
          return out;
        }
      std::uint64_t digits   = 0;
      int           exponent = 0;
      if (precision < 1 || precision > 17 || !std::isfinite(x) ||
          !rounded_digits(std::fabs(x), precision, digits, exponent))
        return std::to_chars(out, out + precision_text_room(precision), x,
                             std::chars_format::general, precision)
          .ptr;
      char text[20];
      write_digits(text, precision, digits); // exactly `precision` digits
      int n = precision;
      while (n > 1 && text[n - 1] == '0') // trailing zeros go
        --n;
      if (x < 0)
        *out++ = '-';
      if (exponent < -4 || exponent >= precision)
        {
          *out++ = text[0];
          if (n > 1)
            {
              *out++ = '.';
              out    = std::copy(text + 1, text + n, out);
            }
          return write_exponent(out, exponent);
        }
      if (exponent < 0)
        {
          *out++ = '0';
          *out++ = '.';
          out    = std::fill_n(out, -exponent - 1, '0');
          return std::copy(text, text + n, out);
        }
      const int whole = exponent + 1; // the digits before the point
      if (n <= whole)
        return std::fill_n(std::copy(text, text + n, out), whole - n, '0');
      out    = std::copy(text, text + whole, out);
      *out++ = '.';
      return std::copy(text + whole, text + n, out);
    }

    Recorder::Recorder(const OutputSpec &output)
      : time(output.time)
      , file(std::make_unique<AtomicFile>(output.file))
      , precision(output.precision < 0 ? 6 : output.precision) // as the stream's precision
      , interval(output.interval)
      , interval_tolerance(output.interval_tolerance)
    {
      buffer.resize(2 * flush_size);
    }

    Recorder::~Recorder()
    {
      if (queue)
        queue->drain();
    }

    void
    Recorder::set_queue(std::shared_ptr<OutputQueue> writer)
    {
      queue = writer && writer->threaded() ? std::move(writer) : nullptr;
    }

    bool
    Recorder::due(const double now)
    {
      // relDeltaTTol: the time steps' rounding must not skip a record
      if (interval != 0 && now - next_time < -interval * interval_tolerance)
        return false;
      if (interval != 0)
        next_time = now + interval;
      recorded_time = now;
      return true;
    }

    void
    Recorder::record(const Domain &domain)
    {
      if (!due(domain.time))
        return;
      line.clear();
      if (time)
        line.push_back(domain.time);
      values(domain, line);
      write_line(domain.time, line);
    }

    void
    Recorder::write_line(const double at, const std::vector<double> &numbers)
    {
      if (queue) // the time travels with the line: a write error says which lines it lost
        queue->push(*this, at, numbers);
      else
        append_text(numbers.data(), numbers.size(), at);
    }

    void
    Recorder::consume(const double *numbers, const std::size_t n)
    {
      append_text(numbers + 1, n - 1, numbers[0]);
    }

    void
    Recorder::append_text(const double *numbers, const std::size_t n, const double at)
    {
      text_time = at;
      // room for each number: sign, the digits, the point and an exponent
      const std::size_t room = precision_text_room(precision) + 1;
      if (used + n * room + 1 > buffer.size()) // grows for a long line only
        buffer.resize(used + n * room + 1);
      char *out = buffer.data() + used;
      for (std::size_t i = 0; i < n; ++i)
        {
          if (i > 0)
            *out++ = ' ';
          out = write_precision_text(out, numbers[i], precision);
        }
      *out++ = '\n';
      used   = out - buffer.data();
      if (used > flush_size)
        {
          file->write(buffer.data(), used);
          used = 0;
        }
    }

    void
    Recorder::write_out()
    {
      if (written_out)
        return;
      if (queue)
        {
          queue->drain();
          OutputQueue::take_error(*this);
        }
      file->write(buffer.data(), used);
      used        = 0;
      written_out = true;
    }

    void
    Recorder::put_in_place()
    {
      if (!written_out || placed)
        return;
      file->commit();
      placed = true;
    }

    std::string
    Recorder::placed_path() const
    {
      return placed ? file->path() : std::string();
    }

    NodeRecorder::NodeRecorder(NodeRecorderSpec s)
      : Recorder(s)
      , spec(std::move(s))
    {}

    void
    NodeRecorder::values(const Domain &domain, std::vector<double> &line)
    {
      using Response = NodeRecorderSpec::Response;
      std::map<int, std::vector<double>> reactions;
      if (spec.response == Response::reaction)
        reactions = domain.reactions();
      if (nodes.size() != spec.nodes.size())
        {
          std::vector<const Node *> found; // all or none (node() may throw)
          for (const int tag : spec.nodes)
            found.push_back(&domain.node(tag));
          nodes = std::move(found);
        }
      // -timeSeries: each DOF's series' factor now, added to disp, vel and
      // accel (OpenSees adds 0 without one)
      const auto offset = [&](const std::size_t j) {
        return j < spec.series.size() && spec.series[j] ? spec.series[j]->at(domain.time) : 0.0;
      };
      for (std::size_t n = 0; n < nodes.size(); ++n)
        {
          const Node &node = *nodes[n];
          const int   tag  = spec.nodes[n];
          for (std::size_t j = 0; j < spec.dofs.size(); ++j)
            {
              const unsigned int k = spec.dofs[j];
              switch (spec.response)
                {
                  case Response::disp:
                    line.push_back(node.disp.at(k) + offset(j));
                    break;
                  case Response::vel:
                    line.push_back(node.vel.at(k) + offset(j));
                    break;
                  case Response::accel:
                    line.push_back(node.accel.at(k) + offset(j));
                    break;
                  case Response::reaction:
                    line.push_back(reactions.at(tag).at(k));
                    break;
                }
            }
        }
    }

    ElementRecorder::ElementRecorder(ElementRecorderSpec s)
      : Recorder(s)
      , spec(std::move(s))
    {}

    void
    ElementRecorder::values(const Domain &domain, std::vector<double> &line)
    {
      if (readers.size() != spec.elements.size())
        {
          std::vector<Element::ResponseReader> found; // all or none (they may throw)
          for (const int tag : spec.elements)
            {
              const Element &element = *domain.elements.at(tag);
              if (is_global_force(spec.response) && domain.has_ground_load(element))
                // OpenSees's getResistingForce: with the element's ground-motion load
                found.push_back([&domain, &element](std::vector<double> &values) {
                  const Vector f = domain.force_with_ground_load(element);
                  values.insert(values.end(), f.data(), f.data() + f.size());
                });
              else
                found.push_back(element.response_reader(spec.response));
            }
          readers = std::move(found);
        }
      for (const Element::ResponseReader &read : readers)
        read(line);
    }
  } // namespace opensees
} // namespace poundfe
