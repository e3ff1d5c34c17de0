// SPDX-License-Identifier: Apache-2.0
#pragma once
// ncpost: the umbrella header of the installed library (find_package(ncpost CONFIG REQUIRED),
// target ncpost::ncpost). It brings in the version and the entry points a program needs to post
// CL data as `ncpost post` does: the machine file loader, the error model file, the CL and G-code
// readers, the solvers (nominal and compensated), the tolerance subdivider, the NC writer and its
// dialects, the post itself with its verification figures, and the entry point that does all of
// `ncpost post` from a stream to a stream (ncpost::post, <ncpost/postproc/post_request.hpp>). The module headers
// (<ncpost/kinematics/...>, <ncpost/machines/...>, <ncpost/compensation/...>, <ncpost/postproc/...>)
// can be included one by one instead. Reference: docs/ (conventions, file formats, CLI).
//
// Units inside the library: lengths in mm, angles in radians; degrees only in files and NC words.

#include "ncpost/version.hpp"

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"

#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/compensation/model_json.hpp"

#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/read/cl_input.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/solve/motion_solver.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"
#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/verify/post_report.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/machine/trr_xy_post_machine.hpp"
#include "ncpost/postproc/solve/tolerance_subdivider.hpp"
#include "ncpost/postproc/verify/verify.hpp"
