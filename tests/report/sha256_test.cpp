// SPDX-License-Identifier: Apache-2.0
// SHA-256 against the FIPS 180-4 / NIST example vectors, across block boundaries and in pieces.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "ncpost/report/sha256.hpp"

using ncpost::report::Sha256;
using ncpost::report::sha256_hex;

TEST_CASE("SHA-256 of the NIST example messages", "[report][sha256]") {
  CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(sha256_hex("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmnopqrlmnopqrsmno"
                   "pqrstnopqrstu") == "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
  CHECK(sha256_hex("The quick brown fox jumps over the lazy dog") ==
        "d7a8fbb307d7809469ca9abcb0082e4f8d5651e46d3cdb762d02d0bf37c9e592");
}

TEST_CASE("SHA-256 of a million 'a' fed in uneven pieces", "[report][sha256]") {
  Sha256 s;
  const std::string piece(997, 'a');
  std::size_t fed = 0;
  while (fed + piece.size() <= 1000000) {
    s.update(piece);
    fed += piece.size();
  }
  s.update(std::string(1000000 - fed, 'a'));
  CHECK(s.hex() == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("SHA-256 of a file equals that of its bytes; a missing file has none", "[report][sha256]") {
  {
    std::ofstream f("sha256_test.bin", std::ios::binary);
    for (int i = 0; i < 70000; ++i) f.put(static_cast<char>(i * 7 + 3));
  }
  std::string bytes;
  for (int i = 0; i < 70000; ++i) bytes += static_cast<char>(i * 7 + 3);
  const auto h = ncpost::report::file_sha256_hex("sha256_test.bin");
  REQUIRE(h);
  CHECK(*h == sha256_hex(bytes));
  CHECK_FALSE(ncpost::report::file_sha256_hex("no_such_file.csv"));
}
