"""Result: one wound reel as numpy arrays (from reelsim.run or reelsim.read)."""

from dataclasses import dataclass, field

import numpy as np


@dataclass(eq=False)  # == of numpy arrays is not a truth value: compare fields with numpy
class Result:
    """One wound reel. Per-layer arrays (index 0 = the layer on the core), SI units,
    stresses compression negative, pressures compression positive (docs/output.md):

    radius            m, outer radius of each layer
    sigma_r           Pa, final radial stress at each layer's outer radius
    sigma_theta       Pa, final hoop stress of each layer
    pressure          Pa, interlayer pressure, 0 - sigma_r
    wound_on_tension  N/m, wound-on tension T0 as the layer joined the roll
    web_tension       N/m, web tension from the tension recipe
    nip_load          N/m, nip load when the layer was wound on (0 without a nip)
    core_pressure     Pa, pressure on the core
    wall_seconds      s, wall-clock time of the winding
    title             the scene's title

    Winding at speed (empty arrays, NaN, when the scene did not call for the effect):
    air_film              m, entrained air film under each layer in the wound reel
                          (compressed by the final pressure; /layers/air_film)
    air_film_entrained    m, the film as it went on (/layers/air_film_entrained)
    at_speed_sigma_r      Pa, radial stress with the roll spinning (centrifugal load;
                          /final_at_speed/sigma_r; sigma_r is then the roll at rest)
    at_speed_sigma_theta  Pa, hoop stress with the roll spinning
    at_speed_core_pressure  Pa, core pressure with the roll spinning

    complete          False for a partial run: a file written when the winding stopped
                      early (root attribute complete = 0); True for a run and for files
                      without the attribute
    Beyond the final profile (None, {} when absent):
    defects   the verdicts of docs/defects.md on the final reel, {rule: {"verdict": "ok" |
              "risk" | "present" | "not assessed", figures...}} for the rules "starring"
              (figures "criterion", "layers", "margin_min", "margin_radius",
              "packet_margin", "strength_margin", "mode", "zone_from_core", "zone_to_core",
              "interlayers"), "slip" ("layers", "margin_min", "margin_radius",
              "capstan_layers"), "hoop_compression", "pressure", "core" (figures as the
              run file's /defects/<rule> attributes); NaN / "" where not assessed
    storage   a reelsim.Storage: the roll through the scene's storage stages
              (docs/storage.md), None when the scene has none
    history   a reelsim.History: the roll at stages of the winding
              (output.history_every), None without
    name      the run's name in a compare file ("2-lo"), else ""
    lanes     lanes across the width (docs/lanes.md), None without: a dict of numpy
              arrays, per lane "x", "width", "caliper", "core_pressure", "outer_radius",
              per layer "strain", layers x lanes "wound_on_tension", "web_tension",
              "slack", "nip_load" (with a nip), "final_sigma_r", "final_sigma_theta",
              "final_radius" (/lanes in the run file); the per-layer arrays above are
              then the width-weighted means of the lanes'
    """

    radius: np.ndarray
    sigma_r: np.ndarray
    sigma_theta: np.ndarray
    pressure: np.ndarray
    wound_on_tension: np.ndarray
    core_pressure: float
    wall_seconds: float
    web_tension: np.ndarray = field(default_factory=lambda: np.empty(0))
    nip_load: np.ndarray = field(default_factory=lambda: np.empty(0))
    title: str = ""
    air_film: np.ndarray = field(default_factory=lambda: np.empty(0))
    air_film_entrained: np.ndarray = field(default_factory=lambda: np.empty(0))
    at_speed_sigma_r: np.ndarray = field(default_factory=lambda: np.empty(0))
    at_speed_sigma_theta: np.ndarray = field(default_factory=lambda: np.empty(0))
    at_speed_core_pressure: float = float("nan")
    complete: bool = True
    defects: dict = field(default_factory=dict)
    storage: object = None
    history: object = None
    name: str = ""
    lanes: object = None

    @property
    def layers(self):
        """Number of layers wound."""
        return int(self.radius.shape[0])

    def __repr__(self):
        outer = self.radius[-1] if self.layers else float("nan")
        return (f"<reelsim.Result {self.title!r}: {self.layers} layers to r = {outer:.6g} m, "
                f"core pressure {self.core_pressure:.6g} Pa>")
