// SPDX-License-Identifier: Apache-2.0
#pragma once
// Test helpers over CL records: every record a reader gives, and the records of one kind; the
// message of the input error a read throws.
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "ncpost/machines/input_error.hpp"
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

/// The motions a reader gives until the end of its input, and its notices, one a line.
struct MotionsAndNotices {
  std::vector<cl::Motion> motions;
  std::string notices;
};

template <class Reader>
MotionsAndNotices motions_and_notices(Reader& reader) {
  MotionsAndNotices out;
  out.motions = only<cl::Motion>(all_records(reader));
  for (const std::string& n : reader.take_notices()) out.notices += n + "\n";
  return out;
}

/// The message of the InputError `read()` throws, "" when it throws none.
template <class Read>
std::string input_error_of(Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

}  // namespace ncpost::test
