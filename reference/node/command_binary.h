// command_binary.h — the compact binary form of commands, for fuzzing.
//
// Spec: docs/spec_facts.md (field widths); docs/commands.md (layout).
//
// A command is one tag byte (its index in the Command variant, 0..21),
// then its fields in wire order, little-endian, fixed width: uint8/16/32,
// real32 and real64 as their IEEE-754 bits, a name as one length byte and
// that many bytes. No padding, no version: a stream is commands back to back.
// Decoding returns a status and never throws; any byte string is safe input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "command.h"

namespace vgc {

enum class DecodeStatus { Ok, End, BadTag, Truncated };
const char* decode_status_name(DecodeStatus s);

// Appends the encoding of `c`. Names longer than 255 bytes cannot be
// encoded: returns false and appends nothing.
bool encode_command(const Command& c, std::string* out);

// Decodes one command from data[*pos...]; on Ok advances *pos. End when
// *pos == size. On any other status *pos is left unchanged.
DecodeStatus decode_command(const std::uint8_t* data, std::size_t size, std::size_t* pos,
                            Command* out);

// Decodes a whole stream; stops at the first malformed command and returns
// its status (End when all bytes were commands).
DecodeStatus decode_commands(const std::uint8_t* data, std::size_t size, std::vector<Command>* out);

}  // namespace vgc
