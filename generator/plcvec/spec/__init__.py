"""Loading and validating the YAML specification (spec/*.yaml)."""
