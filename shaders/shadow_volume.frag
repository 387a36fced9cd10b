// Technique "volume": the volumes only count in the stencil; no colour.
void main() {}
