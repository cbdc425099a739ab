"""Sound files written through libsndfile (ctypes), for the tests that read them: the command-line tests
here and the Python module's (python/tests/test_measurement.py puts this folder on its path)."""
import ctypes
import ctypes.util
import struct

import numpy as np
import pytest


def write_pcm16(path, x, rate, major):
    """x (frames x channels, int16 values) as a 16-bit sound file of the major format MAJOR (SF_FORMAT_WAV,
    _AIFF, _FLAC ...) at RATE Hz, through libsndfile (SF_INFO: frames, samplerate, channels, format, sections,
    seekable); skips the test where libsndfile is not found."""
    name = ctypes.util.find_library("sndfile")
    if not name:
        pytest.skip("libsndfile not found for writing test sound files")
    lib = ctypes.CDLL(name)
    lib.sf_open.restype = ctypes.c_void_p
    lib.sf_open.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_void_p]
    lib.sf_writef_short.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int64]
    lib.sf_close.argtypes = [ctypes.c_void_p]
    x = np.ascontiguousarray(np.asarray(x).reshape(len(x), -1).astype("<i2"))
    info = struct.pack("<qiiiii", 0, rate, x.shape[1], major | 0x0002, 0, 0)
    f = lib.sf_open(str(path).encode(), 0x20, ctypes.create_string_buffer(info, len(info)))
    assert f, f"libsndfile cannot write {path}"
    lib.sf_writef_short(f, x.ctypes.data, len(x))
    lib.sf_close(f)
