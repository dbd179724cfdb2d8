"""Physical models of the satellite and its environment (issue 12 regrouping)."""
