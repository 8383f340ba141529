"""blockdem from Python: scenarios, simulations stepped from Python, numpy views of the state.

The physics is the C++ library's (the extension blockdem._core); see docs/python.md.
"""
from blockdem._core import (  # noqa: F401  (the public API)
    InputError,
    OutputError,
    Scenario,
    Simulation,
    Simulation3d,
    SimulationError,
)
# The laws, the sensor filter and the rocking calibration (python/bind_laws.cpp, bind_calibration.cpp).
from blockdem._core import (  # noqa: F401
    butterworth_filter,
    butterworth_magnitude,
    calibrate_rocking,
    contact_point_history,
    damping_ratio_paper,
    damping_ratio_rebound,
    joint_point_history,
    restitution_no_tension,
    restitution_paper,
)
# Studies and the analysis helpers (python/bind_study.cpp, bind_analysis.cpp, study.py).
from blockdem._core import (  # noqa: F401
    Motion,
    housner_rocking,
    integrate_record,
    intensity_measures,
    limit_analysis,
    process_record,
    read_record,
    response_spectrum,
    rigid_plastic_sliding,
)
from blockdem.study import sweep  # noqa: F401

__all__ = ["InputError", "OutputError", "Scenario", "Simulation", "Simulation3d", "SimulationError",
           "Motion", "housner_rocking", "integrate_record", "intensity_measures", "limit_analysis", "process_record", "read_record",
           "response_spectrum", "rigid_plastic_sliding", "sweep",
           "butterworth_filter", "butterworth_magnitude", "calibrate_rocking", "contact_point_history",
           "damping_ratio_paper", "damping_ratio_rebound", "joint_point_history", "restitution_no_tension",
           "restitution_paper"]
