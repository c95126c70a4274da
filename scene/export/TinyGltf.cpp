// tinygltf's implementation, compiled once for the program, without its image codecs (the `tinygltf`
// target's definitions, CMakeLists.txt). Its own file writing is there but unused: the exporter takes the
// document from a stream and writes every file itself (GltfExport.cpp).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
