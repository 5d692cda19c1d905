// XXH64, the framebuffer checksum (Framebuffer::checksum): the stream format's own
// (protocol/xxhash64.h, which the checksums of stream format version 4 use too), under the
// controller's names.
#pragma once

#include "protocol/xxhash64.h"

namespace fb89::controller {

using protocol::Xxh64;
using protocol::xxh64;

}  // namespace fb89::controller
