// Stub noise.
