#include "ncpost/postproc/cl_record.hpp"
