// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/cl_record.hpp"
