// A measured signal in a sound file, through libsndfile (WAV, FLAC, AIFF, AU, CAF, W64, Ogg, ...).
// libsndfile reads integer PCM as fractions of full scale (±1: a 16-bit sample / 32768), float data as
// stored; --scale turns either into physical units. Channels are channel_1..channel_N: these formats
// carry no channel names.
#include <sndfile.h>

#include <cmath>
#include <memory>
#include <vector>

#include "src/error.hpp"
#include "src/io/signal_file.hpp"

namespace rollspec::io {

namespace {
struct SndfileCloser {
  void operator()(SNDFILE* f) const { sf_close(f); }
};

// libsndfile's message without its closing full stop: ours goes on after it.
std::string sndfile_says(SNDFILE* f) {
  std::string m = sf_strerror(f);
  while (!m.empty() && (m.back() == '.' || m.back() == '\n')) m.pop_back();
  return m;
}

bool is_float(int format) {
  const int sub = format & SF_FORMAT_SUBMASK;
  return sub == SF_FORMAT_FLOAT || sub == SF_FORMAT_DOUBLE;
}

// libsndfile shortens a WAV or AIFF whose data chunk claims more bytes than the file holds to what is
// there, and says so only in its log ("data : 8192 (should be 3000)"): a file cut short is refused.
std::string data_chunk_cut_short(SNDFILE* f) {
  std::string log(1 << 14, '\0');
  sf_command(f, SFC_GET_LOG_INFO, log.data(), static_cast<int>(log.size()));
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  std::size_t start = 0;
  while (start < log.size()) {
    std::size_t end = log.find('\n', start);
    if (end == std::string::npos) end = log.size();
    std::string line = log.substr(start, end - start);
    start = end + 1;
    const auto first = line.find_first_not_of(' ');
    if (first == std::string::npos) continue;
    line = line.substr(first);
    const bool data_chunk = line.rfind("data ", 0) == 0 || line.rfind("SSND ", 0) == 0;
    if (data_chunk && line.find("(should be") != std::string::npos) return line;
  }
  return {};
}

std::string format_name(int format) {
  SF_FORMAT_INFO major{}, sub{};
  major.format = format & SF_FORMAT_TYPEMASK;
  sub.format = format & SF_FORMAT_SUBMASK;
  std::string s =
      sf_command(nullptr, SFC_GET_FORMAT_INFO, &major, sizeof major) == 0 && major.name ? major.name : "sound file";
  if (sf_command(nullptr, SFC_GET_FORMAT_INFO, &sub, sizeof sub) == 0 && sub.name) s += std::string(", ") + sub.name;
  return s;
}
}  // namespace

SignalTable read_sound_signal(const std::string& path) {
  SF_INFO info{};
  const std::unique_ptr<SNDFILE, SndfileCloser> f(sf_open(path.c_str(), SFM_READ, &info));
  if (!f)
    throw data_error(
        path + ": cannot read it as a sound file: " + sndfile_says(nullptr) +
        "; allowed: a file libsndfile reads (WAV, FLAC, AIFF, AU, CAF, W64, Ogg, ...), or CSV text or a .mat file");
  if (info.channels < 1 || info.samplerate < 1)
    throw data_error(path + ": the header gives " + std::to_string(info.channels) + " channels at " +
                     std::to_string(info.samplerate) + " Hz; allowed: at least one channel and a sample rate >= 1 Hz");
  sf_command(f.get(), SFC_SET_NORM_DOUBLE, nullptr, SF_TRUE);  // the default; said here because --help relies on it
  SignalTable s;
  s.file = path;
  s.format = format_name(info.format);
  s.unit = is_float(info.format) ? "as stored" : "full scale";
  s.sample_rate = info.samplerate;
  s.rate_source = "the file header";
  const auto nch = static_cast<std::size_t>(info.channels);
  s.values.assign(nch, {});
  for (std::size_t c = 0; c < nch; ++c) {
    s.channels.push_back("channel_" + std::to_string(c + 1));
    s.groups.push_back(s.channels.back());
  }
  // Read in blocks: the frame count of a damaged header is not to be trusted with an allocation.
  constexpr sf_count_t block = 1 << 14;
  std::vector<double> buf(static_cast<std::size_t>(block) * nch);
  std::size_t frame = 0;
  for (;;) {
    const sf_count_t got = sf_readf_double(f.get(), buf.data(), block);
    if (got <= 0) break;
    for (sf_count_t i = 0; i < got; ++i, ++frame)
      for (std::size_t c = 0; c < nch; ++c) {
        const double v = buf[static_cast<std::size_t>(i) * nch + c];
        if (!std::isfinite(v))
          throw data_error(path + ": " + s.channels[c] + " sample " + std::to_string(frame + 1) +
                           " is not finite; allowed: finite samples");
        s.values[c].push_back(v);
      }
  }
  if (sf_error(f.get()) != SF_ERR_NO_ERROR)
    throw data_error(path + ": cannot read the samples after frame " + std::to_string(frame) + ": " +
                     sndfile_says(f.get()) + "; allowed: an undamaged sound file");
  if (frame == 0)
    throw data_error(path + ": no samples (" + s.format + "); allowed: a sound file with at least one frame");
  // A damaged or cut file must not become a shorter signal in silence: every frame the header
  // declares is read, or the file is refused.
  if (info.frames > 0 && info.frames != SF_COUNT_MAX && static_cast<sf_count_t>(frame) != info.frames)
    throw data_error(path + ": the header declares " + std::to_string(info.frames) + " frames but only " +
                     std::to_string(frame) + " could be read (" + s.format +
                     "): the file is cut short or damaged; allowed: an undamaged sound file");
  const std::string cut = data_chunk_cut_short(f.get());
  if (!cut.empty())
    throw data_error(path + ": the sample data is shorter than the header declares (libsndfile: '" + cut +
                     "' bytes): the file is cut "
                     "short or damaged (a recorder stopped while writing?); allowed: an undamaged sound file");
  return s;
}

}  // namespace rollspec::io
