"""Coverage models: the dimensions each family's rules vary, the combinations the vectors must
exercise, the vectors' own cells (from the engine's record), and a greedy pairwise construction."""
