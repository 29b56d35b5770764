"""Sequences of bangs between two balls, the floor and the ceiling (chapters 4-5).

Collisions are independent (the book's independent collision model, ICM, Fig. 4.3b): each
bang is a two-body collision completed before the next begins, so that between bangs the balls
move at constant velocity along straight space-time lines (Fig. 4.6-4.7). Ball 1 (mass m1) is
below ball 2 (mass m2); the floor (at height ``floor``, below ball 1) and the ceiling (at height
``ceiling``, above ball 2) are infinite masses at rest. Velocities and heights are positive up.

Bang kinds follow the book's labels: ``"01"`` ball 1 off the floor (Bang-1(01)), ``"12"`` ball 1
hits ball 2 (Bang-2(12)), ``"02"`` ball 2 off the ceiling (Bang-3(20), Bang-11(02)); 0 is the
Earth, floor or ceiling. Collisions come from ``mechmodel.collisions.collide``.

Functions take floats, ints, ``Fraction`` or mpmath numbers: exact with ``Fraction`` inputs
(every bang, time and height is then a rational number), floats otherwise.

The submodules, re-exported here (the catalog names them ``bangs.function``):

- ``bounces``: single bangs of chapter 4: floor and ceiling bounces and their impulses, the X2
  launcher (Fig. 4.1, 4.4, 4.5), Galileo-shifted collisions, the Earth's share (Fig. 4.2a).
- ``sequences``: velocity-only sequences under a ceiling (Fig. 5.1, (5.3)-(5.4)) and the book's
  Bang-n numbering of them.
- ``counts``: bang counts and states in O(1) from the rotation picture ((5.6), (5.12)-(5.13)).
- ``histories``: event-driven space-time histories between floor and ceiling (Fig. 4.6-4.12).
"""

from __future__ import annotations

from mechmodel.bangs.bounces import BangChanges as BangChanges
from mechmodel.bangs.bounces import EarthRecoil as EarthRecoil
from mechmodel.bangs.bounces import ShiftedCollision as ShiftedCollision
from mechmodel.bangs.bounces import X2Launch as X2Launch
from mechmodel.bangs.bounces import bang_changes as bang_changes
from mechmodel.bangs.bounces import bounce_impulse as bounce_impulse
from mechmodel.bangs.bounces import ceiling_bounce as ceiling_bounce
from mechmodel.bangs.bounces import earth_recoil as earth_recoil
from mechmodel.bangs.bounces import figures_of_agreement as figures_of_agreement
from mechmodel.bangs.bounces import floor_bounce as floor_bounce
from mechmodel.bangs.bounces import floor_impulse as floor_impulse
from mechmodel.bangs.bounces import galileo_shifted_collision as galileo_shifted_collision
from mechmodel.bangs.bounces import mass_ratio as mass_ratio
from mechmodel.bangs.bounces import sagitta_small_spot_depth as sagitta_small_spot_depth
from mechmodel.bangs.bounces import x2_final_locus_angle as x2_final_locus_angle
from mechmodel.bangs.bounces import x2_full_transfer_ratio as x2_full_transfer_ratio
from mechmodel.bangs.bounces import x2_infinite_ratio_launch as x2_infinite_ratio_launch
from mechmodel.bangs.bounces import x2_launch as x2_launch
from mechmodel.bangs.counts import BangCount as BangCount
from mechmodel.bangs.counts import bang_count as bang_count
from mechmodel.bangs.counts import state_after_bangs as state_after_bangs
from mechmodel.bangs.histories import Event as Event
from mechmodel.bangs.histories import History as History
from mechmodel.bangs.histories import bang_history as bang_history
from mechmodel.bangs.sequences import BALLS as BALLS
from mechmodel.bangs.sequences import CEILING as CEILING
from mechmodel.bangs.sequences import FLOOR as FLOOR
from mechmodel.bangs.sequences import Bang as Bang
from mechmodel.bangs.sequences import BangKind as BangKind
from mechmodel.bangs.sequences import BangSequence as BangSequence
from mechmodel.bangs.sequences import bang_possible as bang_possible
from mechmodel.bangs.sequences import bangs_in_chain as bangs_in_chain
from mechmodel.bangs.sequences import ceiling_sequence as ceiling_sequence
from mechmodel.bangs.sequences import game_over_bang as game_over_bang
from mechmodel.bangs.sequences import velocities_after_bang as velocities_after_bang
from mechmodel.ellipse import energy_ellipse as energy_ellipse  # the catalog names bangs.*

__all__ = [
    "BALLS",
    "CEILING",
    "FLOOR",
    "Bang",
    "BangChanges",
    "BangCount",
    "BangKind",
    "BangSequence",
    "EarthRecoil",
    "Event",
    "History",
    "ShiftedCollision",
    "X2Launch",
    "bang_changes",
    "bang_count",
    "bang_history",
    "bang_possible",
    "bangs_in_chain",
    "bounce_impulse",
    "ceiling_bounce",
    "ceiling_sequence",
    "earth_recoil",
    "energy_ellipse",
    "figures_of_agreement",
    "floor_bounce",
    "floor_impulse",
    "galileo_shifted_collision",
    "game_over_bang",
    "mass_ratio",
    "sagitta_small_spot_depth",
    "state_after_bangs",
    "velocities_after_bang",
    "x2_final_locus_angle",
    "x2_full_transfer_ratio",
    "x2_infinite_ratio_launch",
    "x2_launch",
]
