#pragma once
// Every field of a SimulationCheckpoint but the integrator's memory (Integrator::archive_memory),
// listed once for both saving and loading (math/state_archive.hpp). A field added to any of the
// structs a checkpoint holds (DriverPosition, HybridState and the contact statuses and records
// in it, RowBaseline, ConservationReport, RowExtras) is added here, or a resumed run from a file
// is not the run that never stopped (tests/checkpoint_test.cpp goes through the file).
#include "tumble/math/state_archive.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {

void archive_checkpoint_fields(StateArchive& archive, SimulationCheckpoint& checkpoint);

}  // namespace tumble
