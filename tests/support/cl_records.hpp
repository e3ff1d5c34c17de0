// SPDX-License-Identifier: Apache-2.0
#pragma once
// Test helpers over CL records: every record a reader gives, and the records of one kind.
#include <utility>
#include <variant>
#include <vector>

#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost::test {

/// Every record `reader` gives until the end of its input (AptReader, GcodeClReader, ...).
template <class Reader>
std::vector<cl::Record> all_records(Reader& reader) {
  std::vector<cl::Record> out;
  while (auto x = reader.next()) out.push_back(std::move(*x));
  return out;
}

/// The records of kind T (cl::Motion, cl::Comment, ...), in order.
template <class T>
std::vector<T> only(const std::vector<cl::Record>& records) {
  std::vector<T> out;
  for (const auto& r : records)
    if (const T* x = std::get_if<T>(&r)) out.push_back(*x);
  return out;
}

}  // namespace ncpost::test
