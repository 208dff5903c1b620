// checkpoint_log.h — the checkpoints of a render as they come: a table row
// each on the render's output (seconds, spp, MSE, relMSE and MAE against the
// reference, the estimated relMSE), and a line each in --report's CSV file.
// The error columns stay empty without a reference.
#pragma once

#include <fstream>
#include <ostream>
#include <string>

#include "render/progressive_render.h"

namespace wf {

class CheckpointLog {
public:
    // Prints the table's header; opens and heads the CSV file when `csv_path`
    // is given, or throws InputError when it cannot be written.
    CheckpointLog(std::ostream& table, const std::string& csv_path);

    void add(const Checkpoint& c);

private:
    std::ostream& table_;
    std::ofstream csv_;
};

} // namespace wf
