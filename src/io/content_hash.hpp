#pragma once
// Content hashes, the two rollspec uses.
//
// SHA-256 of a file's or a text's bytes (OpenSSL's libcrypto), as lower-case hex: what `sha256sum`
// prints, so a user can check a recorded hash with standard tools. Records which file a PSD was
// computed from, and that a CSV is the one rollspec wrote (psd_csv.hpp).
//
// FNV-1a, 64 bits: the key of a cache and the checksum of a file rollspec keeps for itself. Fast and
// not cryptographic; its values are stored on disk (table file names and input hashes, checkpoint
// chunk headers and checksums, fit journal keys), so it must never change. What a collision (odds
// about n^2 / 2^65 among n different inputs) would cost where it keys something:
//   - cached tables (stiffness/cached_table.cpp): the hash names the file, but reuse also compares the
//     stored inputs text, so two studies that collide share a file name and the second is refused
//     ("hash matches but its inputs differ", --rebuild), never given the other's table;
//   - checkpoints (scenes::study_result_hash, ensemble/checkpoint.cpp): a chunk from another study with
//     the same hash would pass the chunk header's check, but --resume first compares the manifest's whole
//     resolved study and build, so it cannot mix studies in a directory whose manifest is intact;
//   - fit journals (cli/fit_journal.cpp): the key is all the journal keeps of its inputs, so a colliding
//     fit would reuse another fit's evaluations (wrong likelihoods, silently);
//   - checksums (chunks, manifests, table data): damage would go unseen once in 2^64.
#include <cstddef>
#include <cstdint>
#include <string>

namespace rollspec::io {

constexpr std::uint64_t kFnv1a64Start = 14695981039346656037ull;  // FNV's 64-bit offset basis

// FNV-1a over n bytes, continuing from h (the hash of the bytes before them, or kFnv1a64Start).
std::uint64_t fnv1a64(const void* data, std::size_t n, std::uint64_t h = kFnv1a64Start);
std::uint64_t fnv1a64(const std::string& bytes);

// A 64-bit hash as the 16 lower-case hex digits file names and records carry.
std::string hex16(std::uint64_t h);

std::string sha256_hex(const std::string& bytes);

// Throws missing_input if the file cannot be opened, data_error if it cannot be read to its end.
std::string sha256_file(const std::string& path);

}  // namespace rollspec::io
