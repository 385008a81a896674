"""The shared library libreelsim, loaded once with ctypes.

Where it is: $REELSIM_LIBRARY when set, else what the build wrote into _libpath.py (the
built library in a build tree; for an installed package, the library relative to the
package, then at the configured install prefix). Only functions are declared here: no C
struct is mirrored (a result is read through its typed accessors, rs_reel_result_<field>,
called by the field's name), so the package does not depend on the layout of the
library's structs.
"""

import ctypes
import os

from . import _libpath


def _candidates():
    env = os.environ.get("REELSIM_LIBRARY")
    if env:
        return [env]
    here = os.path.dirname(os.path.abspath(__file__))
    return [p if os.path.isabs(p) else os.path.normpath(os.path.join(here, p))
            for p in _libpath.LIBRARIES]


def _load():
    tried = []
    for path in _candidates():
        if os.path.exists(path):
            return ctypes.CDLL(path)
        tried.append(path)
    raise ImportError("reelsim: cannot find libreelsim (looked for " + ", ".join(tried) +
                      "; set REELSIM_LIBRARY to the library's path)")


lib = _load()

_c = ctypes
_VP = _c.c_void_p
_CP = _c.c_char_p


def _fn(name, restype, *argtypes):
    f = getattr(lib, name)
    f.restype = restype
    f.argtypes = list(argtypes)
    return f


# rs_status is a C enum: an int
rs_version = _fn("rs_version", _CP)
rs_error_message = _fn("rs_error_message", _CP)
rs_error_status = _fn("rs_error_status", _c.c_int)
rs_error_clear = _fn("rs_error_clear", None)
rs_status_name = _fn("rs_status_name", _CP, _c.c_int)
rs_scene_load = _fn("rs_scene_load", _c.c_int, _CP, _c.c_int, _c.POINTER(_CP),
                    _c.POINTER(_VP))
rs_scene_load_text = _fn("rs_scene_load_text", _c.c_int, _CP, _CP, _c.c_size_t, _c.c_int,
                         _c.POINTER(_CP), _c.POINTER(_VP))
rs_scene_destroy = _fn("rs_scene_destroy", None, _c.POINTER(_VP))
rs_scene_wind = _fn("rs_scene_wind", _c.c_int, _VP, _VP, _c.POINTER(_VP))
rs_scene_path = _fn("rs_scene_path", _CP, _VP)
rs_scene_title = _fn("rs_scene_title", _CP, _VP)
rs_reel_result_destroy = _fn("rs_reel_result_destroy", None, _c.POINTER(_VP))


def result_array(field):
    """The accessor of a result's array field: const double *rs_reel_result_<field>(res, &n)."""
    return _fn("rs_reel_result_" + field, _c.POINTER(_c.c_double), _VP, _c.POINTER(_c.c_int))


def result_double(field):
    """The accessor of a result's scalar field: double rs_reel_result_<field>(res)."""
    return _fn("rs_reel_result_" + field, _c.c_double, _VP)


rs_reel_result_n_layers = _fn("rs_reel_result_n_layers", _c.c_int, _VP)
rs_reel_result_n_stages = _fn("rs_reel_result_n_stages", _c.c_int, _VP)
rs_reel_result_stage_layers = _fn("rs_reel_result_stage_layers", _c.POINTER(_c.c_int), _VP,
                                  _c.POINTER(_c.c_int))
rs_reel_result_finite = _fn("rs_reel_result_finite", _c.c_int, _VP, _c.POINTER(_CP))
rs_scene_assess_defects = _fn("rs_scene_assess_defects", _c.c_int, _VP, _VP, _c.POINTER(_VP))
rs_defect_report_destroy = _fn("rs_defect_report_destroy", None, _c.POINTER(_VP))
rs_defect_report_value = _fn("rs_defect_report_value", _c.c_double, _VP, _CP)
rs_defect_report_text = _fn("rs_defect_report_text", _CP, _VP, _CP)

# the values of enum rs_status (include/reelsim/status.h)
RS_OK, RS_ERR_INPUT, RS_ERR_SOLVER = 0, 1, 2

# the stack fit (include/reelsim/fit.h)
RS_FIT_MAX_PARAMS = 16
rs_fit_stack_flat = _fn("rs_fit_stack_flat", _c.c_int, _c.c_int, _c.POINTER(_c.c_double),
                        _c.POINTER(_c.c_double), _CP, _c.c_int, _c.POINTER(_c.c_int),
                        _c.c_char_p, _c.POINTER(_c.c_double), _c.POINTER(_c.c_double),
                        _c.POINTER(_c.c_double))

# reading result files (include/reelsim/reader.h): the one implementation of the layout
_DP = _c.POINTER(_c.c_double)
rs_reader_open = _fn("rs_reader_open", _c.c_int, _CP, _c.POINTER(_VP))
rs_reader_close = _fn("rs_reader_close", None, _c.POINTER(_VP))
rs_reader_is_compare = _fn("rs_reader_is_compare", _c.c_int, _VP)
rs_reader_exists = _fn("rs_reader_exists", _c.c_int, _VP, _CP)
rs_reader_inspect = _fn("rs_reader_inspect", _c.c_int, _VP, _CP, _c.POINTER(_c.c_int),
                        _c.POINTER(_c.c_int), _c.POINTER(_c.c_size_t * 2))
rs_reader_read_1d = _fn("rs_reader_read_1d", _c.c_int, _VP, _CP, _c.POINTER(_DP),
                        _c.POINTER(_c.c_size_t))
rs_reader_free_data = _fn("rs_reader_free_data", None, _c.POINTER(_DP))
rs_reader_attr_string = _fn("rs_reader_attr_string", _c.c_int, _VP, _CP, _CP,
                            _c.POINTER(_VP))
rs_reader_free_text = _fn("rs_reader_free_text", None, _c.POINTER(_VP))
rs_reader_attr_double = _fn("rs_reader_attr_double", _c.c_int, _VP, _CP, _CP,
                            _c.POINTER(_c.c_double))
rs_reader_attr_int64 = _fn("rs_reader_attr_int64", _c.c_int, _VP, _CP, _CP,
                           _c.POINTER(_c.c_longlong))
# enum rs_reader_kind
RS_READER_OTHER, RS_READER_FLOAT, RS_READER_INTEGER, RS_READER_STRING = 0, 1, 2, 3
