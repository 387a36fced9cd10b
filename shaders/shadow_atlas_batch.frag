// Technique "map", the shadow atlas's batched casters: depth only, every
// fragment kept (opaque casters: no holes to cut, no colour to write).
void main() {}
