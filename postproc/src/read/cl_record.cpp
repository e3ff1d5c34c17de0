// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/read/cl_record.hpp"
