// render_stats_json.h — `render --stats-json FILE`: the closing report as
// JSON for benchmark drivers (bench/throughput.py), with what the report only
// sums: the counters as read at every iteration.
#pragma once

#include <string>

#include "render/render_report.h"

namespace wf {

// Writes `summary` to `path`; an unwritable path is an InputError.
void write_stats_json(const std::string& path, const RenderSummary& summary);

} // namespace wf
