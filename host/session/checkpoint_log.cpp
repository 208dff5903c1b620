// checkpoint_log.cpp — both are flushed at every row, so that a render
// stopped by force still leaves the rows it had.
#include "session/checkpoint_log.h"

#include <iomanip>

#include "base/errors.h"

namespace wf {

CheckpointLog::CheckpointLog(std::ostream& table, const std::string& csv_path) : table_(table) {
    if (!csv_path.empty()) {
        csv_.open(csv_path);
        if (!csv_) throw InputError(csv_path + ": cannot write the report");
        csv_ << "seconds,spp,mse,relmse,mae,relmse_estimate\n";
    }
    table_ << "   seconds       spp          mse       relmse          mae   relmse est.\n";
}

void CheckpointLog::add(const Checkpoint& c) {
    table_ << std::fixed << std::setprecision(3) << std::setw(10) << c.seconds << std::setw(10) << c.spp
           << std::scientific << std::setprecision(4);
    if (c.error)
        table_ << std::setw(13) << c.error->mse << std::setw(13) << c.error->relmse << std::setw(13) << c.error->mae;
    else
        table_ << std::setw(39) << "";
    if (c.relmse_estimate) table_ << std::setw(14) << *c.relmse_estimate;
    table_ << std::defaultfloat << "\n" << std::flush;
    if (!csv_.is_open()) return;
    csv_ << std::setprecision(9) << c.seconds << "," << c.spp << ",";
    if (c.error) csv_ << c.error->mse << "," << c.error->relmse << "," << c.error->mae;
    else csv_ << ",,";
    csv_ << ",";
    if (c.relmse_estimate) csv_ << *c.relmse_estimate;
    csv_ << "\n" << std::flush;
}

} // namespace wf
