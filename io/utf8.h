// Text a message quotes, cut between UTF-8 characters and never inside one (a path or a value
// from the command line may hold any bytes; a cut inside a character would print as garbage).
#pragma once

#include <cstddef>
#include <string_view>

namespace compare {

// `at` (at most text.size()), moved back to the first byte of the UTF-8 character it falls in:
// past every continuation byte (10xxxxxx).
inline size_t utf8CharacterStart(std::string_view text, size_t at) {
  while (at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) --at;
  return at;
}

}  // namespace compare
