// The guest build compiles tinyobjloader's single header here (natively it links Debian's
// library, built with the same TINYOBJLOADER_USE_DOUBLE).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
