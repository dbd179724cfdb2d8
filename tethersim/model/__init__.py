"""The model layer: satellite record, parameter table, presets, model registry, air."""
