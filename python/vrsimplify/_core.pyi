from typing import Callable, Optional

import numpy as np

__version__: str

def simplify(vertices: np.ndarray, faces: np.ndarray, target_kind: str, target_value: float,
             max_error: float, mode: str, threads: int, simplify_boundary: bool,
             keep_boundary: bool, max_jump: float, feature_angle: float, seams: Optional[np.ndarray], locked: Optional[np.ndarray],
             progress: Optional[Callable[[float], Optional[bool]]]
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict]: ...
def bounding_box_diagonal(vertices: np.ndarray) -> float: ...
def stop_reason_name(code: int) -> str: ...
