"""`plcvec release`: the versioned bundle of the golden set for consumers who do not run Python."""
