"""Writing vectors: canonical JSON files, the manifest, the CSV export, and the exhaustive tier."""
