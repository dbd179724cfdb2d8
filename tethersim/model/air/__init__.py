"""Air density models: Vallado's exponential table and NRLMSISE-00 (pymsis) on a grid."""
from tethersim.model.air.model import AirModel, air_density, solar_cycle_densities

__all__ = ["AirModel", "air_density", "solar_cycle_densities"]
