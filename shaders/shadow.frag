// Depth only: the rasterizer writes the depth the comparison sampler reads.
void main() {}
