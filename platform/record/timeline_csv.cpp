/// @file timeline_csv.cpp
/// @brief A record's values at a time, and its debrief CSV.
#include "platform/record/timeline_csv.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lungar::platform::record {

namespace {

/// Linear between the frames around `s` of what `of` takes from a frame.
template <class Of>
double frames_at(const SessionRecord& r, double s, const Of& of) {
  const auto& f = r.frames;
  if (f.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto after = std::upper_bound(f.begin(), f.end(), s, [](double t, const RecordedFrame& x) { return t < x.s; });
  if (after == f.begin()) return of(f.front());
  if (after == f.end()) return of(f.back());
  const RecordedFrame& a = *(after - 1);
  const double u = after->s > a.s ? (s - a.s) / (after->s - a.s) : 0.0;
  return of(a) + u * (of(*after) - of(a));
}

}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

const std::string& pathologies_at(const SessionRecord& r, double s) {
  static const std::string kNone;
  const auto& f = r.frames;
  const auto after = std::upper_bound(f.begin(), f.end(), s, [](double t, const RecordedFrame& x) { return t < x.s; });
  return after == f.begin() ? kNone : (after - 1)->pathologies;
}

double dv_at(const SessionRecord& r, double s) {
  return frames_at(r, s, [](const RecordedFrame& f) { return f.breath.dv_ml; });
}

std::string timeline_csv(const SessionRecord& r) {
  struct Row {
    double s, t_s;
    std::string kind, user, text;
  };
  std::vector<Row> rows;
  const auto breath_s = [&](double s) { return frames_at(r, s, [](const RecordedFrame& f) { return f.breath.t_s; }); };
  for (const RecordedEvent& e : r.events) rows.push_back({e.s, e.t_s, e.kind, e.user, e.text});
  for (const RecordedTimeline& t : r.timelines) {
    const std::string said = sim::describe(t.timeline);
    rows.push_back({t.s, breath_s(t.s), "pathology timeline", "", said.empty() ? "none" : said});
  }
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    const RecordedFrame& f = r.frames[k];
    if (k == 0 || f.pathologies != r.frames[k - 1].pathologies)
      rows.push_back({f.s, f.breath.t_s, "pathologies drawn", "", f.pathologies.empty() ? "as loaded" : f.pathologies});
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.s < b.s; });
  std::string csv = "session_s,breath_s,kind,user,text,pathologies,dv_ml\n";
  for (const Row& row : rows) {
    char times[64], dv[32];
    std::snprintf(times, sizeof times, "%.3f,%.3f,", row.s, std::isfinite(row.t_s) ? row.t_s : 0.0);
    const double v = dv_at(r, row.s);
    std::snprintf(dv, sizeof dv, "%.1f", std::isfinite(v) ? v : 0.0);
    csv += times + csv_field(row.kind) + "," + csv_field(row.user) + "," + csv_field(row.text) + "," +
           csv_field(pathologies_at(r, row.s)) + "," + (r.frames.empty() ? std::string() : std::string(dv)) + "\n";
  }
  return csv;
}

}  // namespace lungar::platform::record
