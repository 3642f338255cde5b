//! The records the pass works on, one step at a time, in plain f64 (the rapier adapters fill
//! them): a moving body ([`PassBody`]), one of its colliders ([`PassCollider`]) and a pair of
//! colliders of two bodies ([`PassPair`]).

use super::path::StepPath;
use crate::numerics::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;

/// A body that moves over the step.
#[derive(Copy, Clone, Debug)]
pub struct PassBody {
    /// Its path over the step.
    pub path: StepPath,
    /// Whether it is a fast body of the pass's scope (a pair needs one).
    pub fast: bool,
    /// Whether the pass may stop it (a dynamic body; kinematic bodies follow their user).
    pub stoppable: bool,
    /// The time it stops: the step's length `dt` while it is not stopped.
    pub stop: f64,
    /// The largest distance of a point of its colliders from its centre of mass.
    pub reach: f64,
    /// Whether it is a fast body that turns past the pass's `fast_turn`: it is also checked
    /// against the still targets.
    pub turning: bool,
    /// Whether it is a still target (a collider of fixed geometry or of a body asleep, held
    /// at its pose): paired only with a turning body.
    pub still: bool,
}

impl PassBody {
    /// A body on `path`, not stopped.
    pub fn new(path: StepPath, fast: bool, stoppable: bool, reach: f64) -> Self {
        PassBody {
            path,
            fast,
            stoppable,
            stop: path.dt,
            reach,
            turning: false,
            still: false,
        }
    }

    /// A still target at `pose` over a step of `dt` (never fast, never stopped).
    pub fn target(pose: &Pose, dt: f64) -> Self {
        PassBody {
            still: true,
            ..PassBody::new(StepPath::still(pose, dt), false, false, 0.0)
        }
    }

    /// Whether the pass stopped it.
    pub fn stopped(&self) -> bool {
        self.stop < self.path.dt
    }

    /// Whether it still moves after time `t0`: not stopped at or before it.
    pub fn moves_after(&self, t0: f64) -> bool {
        !(self.stopped() && self.stop <= t0)
    }

    /// Its motion over a window that starts at `t0`: its path, or its pose where it stopped
    /// when it stopped at or before `t0`.
    pub fn motion_from(&self, t0: f64) -> NonlinearRigidMotion {
        if self.moves_after(t0) {
            self.path.motion
        } else {
            NonlinearRigidMotion::constant_position(self.path.pose_at(self.stop))
        }
    }

    /// Its pose at the end of the step as the pass leaves it.
    pub fn end_pose(&self) -> Pose {
        self.path.pose_at(self.stop)
    }

    /// An upper bound of how far any point of it moves over a window starting at `t0`.
    pub fn travel_from(&self, t0: f64) -> f64 {
        if self.moves_after(t0) {
            self.path.max_point_travel(self.reach)
        } else {
            0.0
        }
    }
}

/// A collider of a moving body, with its swept box over the step.
#[derive(Copy, Clone, Debug)]
pub struct PassCollider {
    /// Its body (an index into the pass's bodies).
    pub body: u32,
    /// Its pose in its body's frame.
    pub local: Pose,
    /// Its swept box over the step: the box of the segment its body's centre of mass travels,
    /// loosened by the collider's largest distance from that centre (whatever the turn).
    pub min: Vector,
    /// The upper corner of the swept box.
    pub max: Vector,
    /// Whether it is a sensor.
    pub sensor: bool,
}

impl PassCollider {
    /// The collider of `body` (index `index`) posed at `local` in it, whose points are within
    /// `radius` of the body's centre of mass; `sensor` when it is one.
    pub fn new(index: u32, body: &PassBody, local: Pose, radius: f64, sensor: bool) -> Self {
        let (c0, c1) = body.path.com_ends();
        let r = Vector::splat(radius);
        PassCollider {
            body: index,
            local,
            min: c0.min(c1) - r,
            max: c0.max(c1) + r,
            sensor,
        }
    }

    /// The collider of the still target `index` whose box is [`min`, `max`] (its pose is its
    /// body's: `local` is the identity).
    pub fn target(index: u32, min: Vector, max: Vector) -> Self {
        PassCollider {
            body: index,
            local: Pose::IDENTITY,
            min,
            max,
            sensor: false,
        }
    }

    /// Whether the swept boxes of `self` and `other` overlap.
    pub fn overlaps(&self, other: &PassCollider) -> bool {
        self.min.x <= other.max.x && other.min.x <= self.max.x && self.min.y <= other.max.y && other.min.y <= self.max.y
    }

    /// Its motion over a window starting at `t0`, its body being `body`.
    pub fn motion_from(&self, body: &PassBody, t0: f64) -> NonlinearRigidMotion {
        body.motion_from(t0).prepend(self.local)
    }
}

/// A pair of colliders of two moving bodies whose swept boxes overlap.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct PassPair {
    /// The first collider (an index into the pass's colliders; the smaller one).
    pub a: u32,
    /// The second collider.
    pub b: u32,
    /// Whether the pair is solid (stops its bodies); otherwise a sensor pair (events only).
    pub solid: bool,
    /// Its pending first time of impact; infinite when there is none.
    pub time: f64,
}

impl PassPair {
    /// The pair of colliders `a` and `b`, no time yet.
    pub fn new(a: u32, b: u32) -> Self {
        PassPair {
            a: a.min(b),
            b: a.max(b),
            solid: true,
            time: f64::INFINITY,
        }
    }
}
