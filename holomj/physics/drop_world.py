"""The MuJoCo side of spawn-and-drop: one compiled model, parked objects, parallel drops.

The scene is compiled ONCE with every object still to be placed included, parked high above
the scene, 2 m apart. Parked objects take no contact slots: their colliders get
``contype = conaffinity = 0`` in the working :class:`mujoco.MjModel` (it is compiled with them
on, so the per-body broadphase filter lets them collide once switched back on). They fall
freely, touching nothing, during a drop; every committed state puts them back at their parking
pose. Compiling once costs one compile per call instead of one per placed object.

Candidate drops of one object run in parallel, each in its own fresh MjData with its own
single-thread :class:`mujoco.rollout.Rollout` (which releases the GIL) on a worker thread, in
chunks of :data:`CHUNK_STEPS` steps. MuJoCo's island sleeping is switched on while stepping, so
objects at rest cost (almost) nothing and a drop ends as soon as the dropped object falls
asleep instead of after a fixed time. Each drop starts from the committed state with a zero
warm start and a fresh sleep state, so its result depends neither on the thread it ran on nor
on the other candidates.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import mujoco
import numpy as np
from mujoco import rollout

from holomj.mjcf import names
from holomj.mjcf.compiler import CompiledScene
from holomj.physics.bounds import world_aabbs

FULL = mujoco.mjtState.mjSTATE_FULLPHYSICS
SPAWN_CLEARANCE = 5e-4  # a candidate closer than this to any collider is rejected at spawn
SLEEP = int(mujoco.mjtEnableBit.mjENBL_SLEEP)
CHUNK_STEPS = 25  # steps between checks for rest (sleep) during a drop


class _DropRun:
    """One candidate drop: its own MjData (fresh sleep state) and a single-thread Rollout.

    ``Rollout.rollout`` releases the GIL, so runs on different Python threads step in parallel.
    Chunks continue exactly where the last one ended: the same state (no tree is woken) and the
    warm start the data holds.
    """

    def __init__(self, model: mujoco.MjModel) -> None:
        self.data = mujoco.MjData(model)
        self._rollout = rollout.Rollout(nthread=0)
        self.state = np.zeros((1, mujoco.mj_stateSize(model, FULL)))
        self.warm = np.zeros((1, model.nv))
        self.steps = 0
        self.warned = False

    def start(self, model: mujoco.MjModel, state: np.ndarray) -> _DropRun:
        mujoco.mj_resetData(model, self.data)
        # Fill every derived quantity first (sleeping off): stepping a fresh MjData with
        # sleeping on can meet uninitialised frames (MuJoCo 3.17: "contact frame undefined").
        mujoco.mj_setState(model, self.data, state, FULL)
        mujoco.mj_forward(model, self.data)
        self.state = state[None].copy()
        self.warm[:] = 0.0
        self.steps = 0
        self.warned = False
        return self

    def advance(self, model: mujoco.MjModel, nstep: int) -> None:
        out, _ = self._rollout.rollout(
            model, self.data, self.state, nstep=nstep, initial_warmstart=self.warm
        )
        self.state = out[:, -1].copy()
        self.warm = self.data.qacc_warmstart[None].copy()
        self.steps += nstep
        self.warned = any(w.number > 0 for w in self.data.warning)


@dataclass(frozen=True)
class BodyInfo:
    """Indices of one scene object in the compiled model."""

    body: int
    geoms: np.ndarray  # its collision geoms
    qpos: int  # address of its free joint in qpos (-1: no joint)
    dof: int  # address in qvel (-1: no joint)


@dataclass(frozen=True)
class Outcome:
    """The end of one candidate drop."""

    state: np.ndarray  # full physics state after the drop
    position: np.ndarray  # settled origin (footprint bottom centre) of the dropped object
    quat: np.ndarray  # settled orientation (w, x, y, z)
    speed: float  # linear speed, m/s
    spin: float  # angular speed, rad/s
    tilt_deg: float  # angle between its local +Z and the world +Z
    touches: frozenset[int]  # bodies its colliders touch
    finite: bool  # False when the simulation blew up


def tilt_deg(quat: np.ndarray) -> float:
    """Angle in degrees between a frame's +Z axis and the world +Z."""
    _, x, y, _ = quat / np.linalg.norm(quat)
    zz = 1.0 - 2.0 * (x * x + y * y)
    return math.degrees(math.acos(max(-1.0, min(1.0, zz))))


class DropWorld:
    """A compiled scene in which objects are dropped one after another."""

    def __init__(self, compiled: CompiledScene, parked: list[str], *, nthread: int = 1) -> None:
        self.model = compiled.model
        self.data = mujoco.MjData(self.model)
        self._scratch = mujoco.MjData(self.model)
        self.nthread = max(1, nthread)
        m = self.model
        self._slots = [_DropRun(m) for _ in range(self.nthread)]
        self._pool = ThreadPoolExecutor(self.nthread) if self.nthread > 1 else None
        self._collider = (m.geom_contype != 0) | (m.geom_conaffinity != 0)
        self._contype = m.geom_contype.copy()
        self._conaffinity = m.geom_conaffinity.copy()
        self.bodies = {o.id: self._body_info(o.id) for o in compiled.scene.objects}
        self._active = self._collider.copy()
        for object_id in parked:
            self._set_contacts(object_id, enabled=False)
        mujoco.mj_forward(m, self.data)
        self.state = self._get_state(self.data)
        self._parking = {
            object_id: self.data.qpos[self._qslice(object_id)].copy() for object_id in parked
        }
        self._parked = set(parked)

    # -- bookkeeping ------------------------------------------------------------------------

    def _body_info(self, object_id: str) -> BodyInfo:
        m = self.model
        body = m.body(names.object_body(object_id)).id
        geoms = np.flatnonzero((m.geom_bodyid == body) & self._collider)
        qpos = dof = -1
        if m.body_jntnum[body] > 0:
            joint = m.body_jntadr[body]
            qpos, dof = int(m.jnt_qposadr[joint]), int(m.jnt_dofadr[joint])
        return BodyInfo(body=body, geoms=geoms, qpos=qpos, dof=dof)

    def _qslice(self, object_id: str) -> slice:
        adr = self.bodies[object_id].qpos
        return slice(adr, adr + 7)

    def _set_contacts(self, object_id: str, *, enabled: bool) -> None:
        geoms = self.bodies[object_id].geoms
        m = self.model
        m.geom_contype[geoms] = self._contype[geoms] if enabled else 0
        m.geom_conaffinity[geoms] = self._conaffinity[geoms] if enabled else 0
        self._active[geoms] = enabled

    def _get_state(self, data: mujoco.MjData) -> np.ndarray:
        state = np.empty(mujoco.mj_stateSize(self.model, FULL))
        mujoco.mj_getState(self.model, data, state, FULL)
        return state

    def _load(self, state: np.ndarray, *, forward: bool = False) -> mujoco.MjData:
        d = self._scratch
        mujoco.mj_setState(self.model, d, state, FULL)
        if forward:
            mujoco.mj_forward(self.model, d)
        else:
            mujoco.mj_kinematics(self.model, d)
        return d

    def pose(
        self, object_id: str, state: np.ndarray | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """World position and quaternion of an object's body in ``state`` (default: committed)."""
        d = self._load(self.state if state is None else state)
        body = self.bodies[object_id].body
        return d.xpos[body].copy(), d.xquat[body].copy()

    # -- candidates -------------------------------------------------------------------------

    def activate(self, object_id: str) -> None:
        """Give a parked object its contacts back (it is about to be dropped)."""
        self._set_contacts(object_id, enabled=True)

    def park(self, object_id: str) -> None:
        """Take an object's contacts away again (it could not be placed)."""
        self._set_contacts(object_id, enabled=False)

    def candidate_state(self, object_id: str, pos: np.ndarray, quat: np.ndarray) -> np.ndarray:
        """The committed state with ``object_id`` at rest at (pos, quat)."""
        d = self._scratch
        mujoco.mj_setState(self.model, d, self.state, FULL)
        info = self.bodies[object_id]
        d.qpos[info.qpos : info.qpos + 3] = pos
        d.qpos[info.qpos + 3 : info.qpos + 7] = quat
        d.qvel[info.dof : info.dof + 6] = 0.0
        return self._get_state(d)

    def spawn_collision(self, object_id: str, state: np.ndarray) -> str | None:
        """Name of a collider the object touches or overlaps in ``state``, else None.

        A cheap world-AABB test picks the pairs; ``mj_geomDistance`` decides.
        """
        m, d = self.model, self._load(state)
        lo, hi = world_aabbs(self.model, d)
        own = self.bodies[object_id].geoms
        others = self._active.copy()
        others[own] = False
        candidates = np.flatnonzero(others)
        margin = SPAWN_CLEARANCE
        for g in own:
            near = candidates[
                np.all(lo[candidates] <= hi[g] + margin, axis=1)
                & np.all(hi[candidates] >= lo[g] - margin, axis=1)
            ]
            for h in near:
                if mujoco.mj_geomDistance(m, d, int(g), int(h), 0.01, None) < margin:
                    return m.geom(int(h)).name or f"geom {h}"
        return None

    # -- drops ------------------------------------------------------------------------------

    def drop(
        self,
        object_id: str,
        states: list[np.ndarray],
        nstep: int,
        watch: list[str],
        judge: Callable[[int, Outcome], str | None],
        floor_z: float,
    ) -> list[tuple[Outcome | None, str | None]]:
        """Drop ``object_id`` from each candidate state, in parallel, and judge the outcomes.

        A candidate runs until its object and every object in ``watch`` are asleep (at rest),
        its object falls below ``floor_z``, MuJoCo warns, or ``nstep`` steps. ``judge(k,
        outcome)`` says why candidate ``k`` is rejected (None: accepted). Stepping stops as soon
        as the first candidate in order that is not rejected is accepted; candidates after it
        come back as ``(None, None)``.
        """
        info = self.bodies[object_id]
        trees = [int(self.model.body_treeid[info.body])]
        trees += [int(self.model.body_treeid[self.bodies[w].body]) for w in watch]
        trees = sorted({t for t in trees if t >= 0})
        runs = [self._slots[k].start(self.model, state) for k, state in enumerate(states)]
        verdicts: list[tuple[Outcome | None, str | None] | None] = [None] * len(states)
        while True:
            active = [k for k, v in enumerate(verdicts) if v is None]
            first = next((k for k, v in enumerate(verdicts) if v is None or v[1] is None), None)
            if first is None or (verdicts[first] is not None):
                break  # all rejected, or the first survivor is accepted
            chunk = min(CHUNK_STEPS, nstep - max(runs[k].steps for k in active))
            self._step_all([runs[k] for k in active], chunk)
            for k in active:
                run = runs[k]
                z = run.data.qpos[info.qpos + 2]
                asleep = all(run.data.tree_asleep[t] >= 0 for t in trees)
                if run.warned or asleep or z < floor_z or run.steps >= nstep:
                    outcome = self._outcome(object_id, run.state[0], warned=run.warned)
                    verdicts[k] = (outcome, judge(k, outcome))
        return [v if v is not None else (None, None) for v in verdicts]

    def _step_all(self, runs: list[_DropRun], nstep: int) -> None:
        """Advance runs in parallel with sleeping on (only while they step: the checks made
        on the scratch data must see every contact, asleep or not)."""
        m = self.model
        m.opt.enableflags |= SLEEP
        try:
            if len(runs) > 1 and self._pool is not None:
                list(self._pool.map(lambda run: run.advance(m, nstep), runs))
            else:
                for run in runs:
                    run.advance(m, nstep)
        finally:
            m.opt.enableflags &= ~SLEEP

    def _outcome(self, object_id: str, state: np.ndarray, *, warned: bool = False) -> Outcome:
        info = self.bodies[object_id]
        finite = bool(np.all(np.isfinite(state))) and not warned
        if not finite:
            nan = np.full(3, np.nan)
            return Outcome(state, nan, np.array([1.0, 0, 0, 0]), math.inf, math.inf, 180.0,
                           frozenset(), False)  # fmt: skip
        d = self._load(state, forward=True)
        body = info.body
        qvel = d.qvel[info.dof : info.dof + 6]
        touches = set()
        if d.ncon:
            pairs = d.contact.geom[: d.ncon]
            bodies = self.model.geom_bodyid[pairs]
            for b1, b2 in bodies:
                if b1 == body:
                    touches.add(int(b2))
                elif b2 == body:
                    touches.add(int(b1))
        quat = d.xquat[body].copy()
        return Outcome(
            state=state,
            position=d.xpos[body].copy(),
            quat=quat,
            speed=float(np.linalg.norm(qvel[:3])),
            spin=float(np.linalg.norm(qvel[3:])),
            tilt_deg=tilt_deg(quat),
            touches=frozenset(touches),
            finite=True,
        )

    def close(self) -> None:
        """Stop the worker threads."""
        if self._pool is not None:
            self._pool.shutdown()
            self._pool = None

    def commit(self, object_id: str, state: np.ndarray) -> None:
        """Make ``state`` (with ``object_id`` placed) the committed state."""
        self._parked.discard(object_id)
        d = self._scratch
        mujoco.mj_setState(self.model, d, state, FULL)
        for parked in self._parked:
            info = self.bodies[parked]
            d.qpos[info.qpos : info.qpos + 7] = self._parking[parked]
            d.qvel[info.dof : info.dof + 6] = 0.0
        self.state = self._get_state(d)

    def penetration(self, object_id: str) -> float:
        """Deepest penetration (>= 0, metres) of the object's colliders in the committed state."""
        d = self._load(self.state, forward=True)
        body = self.bodies[object_id].body
        deepest = 0.0
        if d.ncon:
            pairs = self.model.geom_bodyid[d.contact.geom[: d.ncon]]
            dist = d.contact.dist[: d.ncon]
            mine = (pairs[:, 0] == body) | (pairs[:, 1] == body)
            if np.any(mine):
                deepest = max(0.0, float(-dist[mine].min()))
        return deepest
