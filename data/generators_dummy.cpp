// Keeps the library non-empty while generators are being written.
