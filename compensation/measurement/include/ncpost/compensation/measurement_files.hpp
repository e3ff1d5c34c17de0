// SPDX-License-Identifier: Apache-2.0
#pragma once
// The measurement files of one identification, read together (issue 14 item 5): each file once.
// A path given twice (the same file by device and inode, whatever its name) or a file whose rows
// repeat an earlier file's rows would count the same measurements twice and shrink the reported
// uncertainties by √2: both are InputErrors naming the file (and the first one). Each set's
// lengths are corrected to 20 °C where its file gives the temperature and the expansion
// coefficient (thermal_correction.hpp).
#include <string>
#include <vector>

#include "ncpost/compensation/measurement_csv.hpp"

namespace ncpost::comp {

std::vector<MeasurementSet> read_measurement_files(const std::vector<std::string>& paths, const Machine& machine,
                                                   const CsvReadOptions& options = {});

/// The index of an earlier set holding the same rows (commands, times and values) as sets[k], or -1.
int same_rows_as_earlier(const std::vector<MeasurementSet>& sets, std::size_t k);

}  // namespace ncpost::comp
