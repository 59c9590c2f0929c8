//! A block of consecutive steps stored as columns (a struct of arrays): each quantity of every
//! body, joint and piston, and each load, one fixed-length array over the block's steps. The
//! step loop fills a block at a time and the summary reads its columns, so that a quantity's
//! values over the block lie side by side (peaks and sums over them vectorise) and no step is
//! reached through a chain of pointers. A lane `i` of a block is one step; [`StateBlock::gather`]
//! gives it as a [`State`] for the code that works a step at a time (per-step files, the
//! general solve).

use crate::model::{BodyMotion, JointLoad, JointMotion, Loads, PistonMotion, PointMotion, State};
use crate::{CrankState, Topology, C};

/// Steps in a block: the length of every column.
pub const LANES: usize = 64;

/// One quantity over the steps of a block, in the unit of the quantity it holds.
pub type Column = [f64; LANES];

/// A column of zeros.
pub const ZERO: Column = [0.0; LANES];

/// The crank state of every step of a block (the fields of [`CrankState`]).
#[derive(Debug, Clone, PartialEq)]
pub struct CrankColumns {
    /// Crank angle θ, rad.
    pub angle: Column,
    /// cos θ and sin θ.
    pub cos: Column,
    pub sin: Column,
    /// ω, rad/s.
    pub speed: Column,
    /// α, rad/s².
    pub acceleration: Column,
    /// Time, s.
    pub time: Column,
}

/// A point's motion over a block (the fields of [`PointMotion`], x and y components).
#[derive(Debug, Clone, PartialEq)]
pub struct PointColumns {
    /// Position, m.
    pub x: Column,
    pub y: Column,
    /// Velocity, m/s.
    pub vx: Column,
    pub vy: Column,
    /// Acceleration, m/s².
    pub ax: Column,
    pub ay: Column,
}

/// A body's motion over a block (the fields of [`BodyMotion`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BodyColumns {
    pub cg: PointColumns,
    /// The orientation's unit vector, x and y components.
    pub orientation_x: Column,
    pub orientation_y: Column,
    /// rad/s.
    pub angular_velocity: Column,
    /// rad/s².
    pub angular_acceleration: Column,
}

/// A joint's motion over a block (the fields of [`JointMotion`]).
#[derive(Debug, Clone, PartialEq)]
pub struct JointColumns {
    /// Position, m.
    pub x: Column,
    pub y: Column,
    /// Direction (unit vector), x and y components.
    pub direction_x: Column,
    pub direction_y: Column,
    /// rad/s for a pin, m/s for a slide or a mesh.
    pub relative_speed: Column,
}

/// A piston's motion over a block (the fields of [`PistonMotion`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PistonColumns {
    /// m.
    pub position: Column,
    /// m/s.
    pub velocity: Column,
    /// m/s².
    pub acceleration: Column,
    /// m/rad.
    pub dx_dtheta: Column,
    /// m/rad².
    pub d2x_dtheta2: Column,
}

/// The states of the steps of a block, in the order of a [`Topology`]: lane `i` of every
/// column is step `i` of the block, for `i < len`.
#[derive(Debug, Clone, PartialEq)]
pub struct StateBlock {
    /// Steps the block holds (at most [`LANES`]).
    pub len: usize,
    pub crank: CrankColumns,
    pub bodies: Vec<BodyColumns>,
    pub joints: Vec<JointColumns>,
    pub pistons: Vec<PistonColumns>,
}

impl CrankColumns {
    /// Zeros in every column.
    pub const ZEROED: Self = Self {
        angle: ZERO,
        cos: ZERO,
        sin: ZERO,
        speed: ZERO,
        acceleration: ZERO,
        time: ZERO,
    };

    /// Lane `i`.
    #[inline(always)]
    pub fn at(&self, i: usize) -> CrankState {
        CrankState {
            angle: self.angle[i],
            direction: C::new(self.cos[i], self.sin[i]),
            speed: self.speed[i],
            acceleration: self.acceleration[i],
            time: self.time[i],
        }
    }

    /// Sets lane `i`.
    #[inline(always)]
    pub fn set(&mut self, i: usize, s: &CrankState) {
        self.angle[i] = s.angle;
        self.cos[i] = s.direction.re;
        self.sin[i] = s.direction.im;
        self.speed[i] = s.speed;
        self.acceleration[i] = s.acceleration;
        self.time[i] = s.time;
    }
}

impl PointColumns {
    /// Sets lane `i`.
    #[inline(always)]
    pub fn set(&mut self, i: usize, m: &PointMotion) {
        self.x[i] = m.position.re;
        self.y[i] = m.position.im;
        self.vx[i] = m.velocity.re;
        self.vy[i] = m.velocity.im;
        self.ax[i] = m.acceleration.re;
        self.ay[i] = m.acceleration.im;
    }
}

impl BodyColumns {
    /// Lane `i`.
    #[inline(always)]
    pub fn at(&self, i: usize) -> BodyMotion {
        let p = &self.cg;
        BodyMotion {
            cg: PointMotion {
                position: C::new(p.x[i], p.y[i]),
                velocity: C::new(p.vx[i], p.vy[i]),
                acceleration: C::new(p.ax[i], p.ay[i]),
            },
            orientation: C::new(self.orientation_x[i], self.orientation_y[i]),
            angular_velocity: self.angular_velocity[i],
            angular_acceleration: self.angular_acceleration[i],
        }
    }

    /// Sets lane `i`.
    #[inline(always)]
    pub fn set(&mut self, i: usize, m: &BodyMotion) {
        self.cg.set(i, &m.cg);
        self.orientation_x[i] = m.orientation.re;
        self.orientation_y[i] = m.orientation.im;
        self.angular_velocity[i] = m.angular_velocity;
        self.angular_acceleration[i] = m.angular_acceleration;
    }
}

impl JointColumns {
    /// Lane `i`.
    #[inline(always)]
    pub fn at(&self, i: usize) -> JointMotion {
        JointMotion {
            position: C::new(self.x[i], self.y[i]),
            direction: C::new(self.direction_x[i], self.direction_y[i]),
            relative_speed: self.relative_speed[i],
        }
    }

    /// Sets lane `i`.
    #[inline(always)]
    pub fn set(&mut self, i: usize, m: &JointMotion) {
        self.x[i] = m.position.re;
        self.y[i] = m.position.im;
        self.direction_x[i] = m.direction.re;
        self.direction_y[i] = m.direction.im;
        self.relative_speed[i] = m.relative_speed;
    }
}

impl PistonColumns {
    /// Lane `i`.
    #[inline(always)]
    pub fn at(&self, i: usize) -> PistonMotion {
        PistonMotion {
            position: self.position[i],
            velocity: self.velocity[i],
            acceleration: self.acceleration[i],
            dx_dtheta: self.dx_dtheta[i],
            d2x_dtheta2: self.d2x_dtheta2[i],
        }
    }

    /// Sets lane `i`.
    #[inline(always)]
    pub fn set(&mut self, i: usize, m: &PistonMotion) {
        self.position[i] = m.position;
        self.velocity[i] = m.velocity;
        self.acceleration[i] = m.acceleration;
        self.dx_dtheta[i] = m.dx_dtheta;
        self.d2x_dtheta2[i] = m.d2x_dtheta2;
    }
}

fn point() -> PointColumns {
    PointColumns {
        x: ZERO,
        y: ZERO,
        vx: ZERO,
        vy: ZERO,
        ax: ZERO,
        ay: ZERO,
    }
}

impl StateBlock {
    /// An empty block with the columns of `topology`.
    pub fn for_topology(topology: &Topology) -> Self {
        let body = BodyColumns {
            cg: point(),
            orientation_x: ZERO,
            orientation_y: ZERO,
            angular_velocity: ZERO,
            angular_acceleration: ZERO,
        };
        let joint = JointColumns {
            x: ZERO,
            y: ZERO,
            direction_x: ZERO,
            direction_y: ZERO,
            relative_speed: ZERO,
        };
        let piston = PistonColumns {
            position: ZERO,
            velocity: ZERO,
            acceleration: ZERO,
            dx_dtheta: ZERO,
            d2x_dtheta2: ZERO,
        };
        Self {
            len: 0,
            crank: CrankColumns::ZEROED,
            bodies: vec![body; topology.bodies.len()],
            joints: vec![joint; topology.joints.len()],
            pistons: vec![piston; topology.pistons.len()],
        }
    }

    /// The steps the block holds (at most [`LANES`]), its crank columns, and its bodies',
    /// joints' and pistons' columns as arrays of the sizes of a mechanism's topology (`None`
    /// for a block of another topology): what a mechanism's fill writes.
    #[allow(clippy::type_complexity)]
    pub fn split<const B: usize, const J: usize, const P: usize>(
        &mut self,
    ) -> Option<(
        usize,
        &CrankColumns,
        &mut [BodyColumns; B],
        &mut [JointColumns; J],
        &mut [PistonColumns; P],
    )> {
        Some((
            self.len.min(LANES),
            &self.crank,
            (&mut self.bodies[..]).try_into().ok()?,
            (&mut self.joints[..]).try_into().ok()?,
            (&mut self.pistons[..]).try_into().ok()?,
        ))
    }

    /// Lane `i` as a state (a [`State::for_topology`] of the same topology), all but its extras.
    pub fn gather(&self, i: usize, st: &mut State) {
        st.crank = self.crank.at(i);
        for (b, c) in st.bodies.iter_mut().zip(&self.bodies) {
            *b = c.at(i);
        }
        for (j, c) in st.joints.iter_mut().zip(&self.joints) {
            *j = c.at(i);
        }
        for (p, c) in st.pistons.iter_mut().zip(&self.pistons) {
            *p = c.at(i);
        }
    }

    /// A block of one lane holding `st`, a state of a mechanism of `topology`: a single step
    /// as a block, for the code written for blocks.
    pub fn of_state(topology: &Topology, st: &State) -> Self {
        let mut block = Self::for_topology(topology);
        block.len = 1;
        block.scatter(0, st);
        block
    }

    /// Sets lane `i` to the state `st`.
    pub fn scatter(&mut self, i: usize, st: &State) {
        self.crank.set(i, &st.crank);
        for (b, c) in st.bodies.iter().zip(&mut self.bodies) {
            c.set(i, b);
        }
        for (j, c) in st.joints.iter().zip(&mut self.joints) {
            c.set(i, j);
        }
        for (p, c) in st.pistons.iter().zip(&mut self.pistons) {
            c.set(i, p);
        }
    }

    /// Fills the block's lanes a state at a time with `fill`, at their crank states (a
    /// mechanism whose kinematics are not written for columns).
    pub fn fill_each(&mut self, topology: &Topology, fill: impl Fn(&CrankState, &mut State)) {
        let mut st = State::for_topology(topology);
        for i in 0..self.len {
            fill(&self.crank.at(i), &mut st);
            self.scatter(i, &st);
        }
    }
}

/// A joint's load over a block (the fields of [`JointLoad`]).
#[derive(Debug, Clone, PartialEq)]
pub struct JointLoadColumns {
    /// Force on the joint's `body` from its `other`, N.
    pub fx: Column,
    pub fy: Column,
    /// Couple, N·m.
    pub moment: Column,
}

impl JointLoadColumns {
    /// Lane `i`.
    #[inline(always)]
    pub fn at(&self, i: usize) -> JointLoad {
        JointLoad {
            force: C::new(self.fx[i], self.fy[i]),
            moment: self.moment[i],
        }
    }

    /// Sets lane `i`'s force (its couple left as it is).
    #[inline(always)]
    pub fn set_force(&mut self, i: usize, force: C) {
        self.fx[i] = force.re;
        self.fy[i] = force.im;
    }

    /// Sets lane `i`.
    #[inline(always)]
    pub fn set(&mut self, i: usize, load: &JointLoad) {
        self.fx[i] = load.force.re;
        self.fy[i] = load.force.im;
        self.moment[i] = load.moment;
    }
}

/// The loads of one family over a block, keyed by joint (the fields of [`Loads`]).
#[derive(Debug, Clone, PartialEq)]
pub struct LoadsBlock {
    pub joints: Vec<JointLoadColumns>,
    /// Drive torque, N·m.
    pub crank_torque: Column,
}

impl LoadsBlock {
    pub fn for_topology(topology: &Topology) -> Self {
        let joint = JointLoadColumns {
            fx: ZERO,
            fy: ZERO,
            moment: ZERO,
        };
        Self {
            joints: vec![joint; topology.joints.len()],
            crank_torque: ZERO,
        }
    }

    /// The joints' columns as an array of the size of a mechanism's topology (`None` for a
    /// block of another topology), and the drive torque's column: what a mechanism's closed
    /// forms write.
    pub fn split<const J: usize>(&mut self) -> Option<(&mut [JointLoadColumns; J], &mut Column)> {
        Some((
            (&mut self.joints[..]).try_into().ok()?,
            &mut self.crank_torque,
        ))
    }

    /// Lane `i` as loads (a [`Loads::for_topology`] of the same topology).
    pub fn gather(&self, i: usize, out: &mut Loads) {
        for (j, c) in out.joints.iter_mut().zip(&self.joints) {
            *j = c.at(i);
        }
        out.crank_torque = self.crank_torque[i];
    }

    /// A block whose lane 0 holds `loads`, loads of a mechanism of `topology` (a single step's).
    pub fn of_loads(topology: &Topology, loads: &Loads) -> Self {
        let mut block = Self::for_topology(topology);
        block.scatter(0, loads);
        block
    }

    /// Sets lane `i` to `loads`.
    pub fn scatter(&mut self, i: usize, loads: &Loads) {
        for (j, c) in loads.joints.iter().zip(&mut self.joints) {
            c.set(i, j);
        }
        self.crank_torque[i] = loads.crank_torque;
    }

    /// Sets the first `n` lanes to zero.
    pub fn clear(&mut self, n: usize) {
        for j in &mut self.joints {
            j.fx[..n].fill(0.0);
            j.fy[..n].fill(0.0);
            j.moment[..n].fill(0.0);
        }
        self.crank_torque[..n].fill(0.0);
    }

    /// Adds `other`'s first `n` lanes (superposition of load families, Karhula A7.1).
    pub fn add(&mut self, other: &LoadsBlock, n: usize) {
        add_loads(self, other, n);
    }
}

crate::vectorised! {
    /// [`LoadsBlock::add`].
    fn add_loads(total: &mut LoadsBlock, other: &LoadsBlock, n: usize) {
        for (a, b) in total.joints.iter_mut().zip(&other.joints) {
            add_column(&mut a.fx, &b.fx, n);
            add_column(&mut a.fy, &b.fy, n);
            add_column(&mut a.moment, &b.moment, n);
        }
        add_column(&mut total.crank_torque, &other.crank_torque, n);
    }
}

/// Adds `b`'s first `n` lanes to `a`'s. Inlined into the kernel (a closure would not take its
/// target features).
#[inline(always)]
fn add_column(a: &mut Column, b: &Column, n: usize) {
    for (a, b) in a[..n].iter_mut().zip(&b[..n]) {
        *a += b;
    }
}

/// Whether the block kernels (`vectorised!`) run their AVX2 versions: where the processor has
/// AVX2, unless the environment sets `CARDAN_SIMD=baseline` (to compare the two: the tests run
/// the shipped cases both ways and find the same bytes). Read once per process, like the
/// processor's features themselves.
pub fn use_avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        static ON: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
        *ON.get_or_init(|| {
            std::is_x86_feature_detected!("avx2")
                && std::env::var_os("CARDAN_SIMD").is_none_or(|v| v != "baseline")
        })
    }
    #[cfg(not(target_arch = "x86_64"))]
    false
}

/// Defines a block kernel (a function over a block's lanes) compiled twice: for AVX2, called
/// where [`use_avx2`] says so, and for the baseline x86-64 (SSE2) elsewhere. The loops over the
/// lanes then work on four numbers at once instead of two (measured: a run about 1.5 times
/// faster). The arithmetic is IEEE's either way (fused multiply-adds are not enabled), so the
/// results are the same bit for bit (tested on the shipped cases). A kernel is a plain function
/// (not a method: a block kernel is reached through a `dyn` trait, so each wraps its own body);
/// what it calls must be inlined into it (`#[inline(always)]`) to be compiled for AVX2 too.
#[macro_export]
macro_rules! vectorised {
    ($(#[$meta:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?)
        $(-> $ret:ty)? $body:block) => {
        $(#[$meta])*
        $vis fn $name($($arg: $ty),*) $(-> $ret)? {
            #[inline(always)]
            fn kernel($($arg: $ty),*) $(-> $ret)? $body
            #[cfg(target_arch = "x86_64")]
            {
                #[target_feature(enable = "avx2")]
                fn avx2($($arg: $ty),*) $(-> $ret)? {
                    kernel($($arg),*)
                }
                if $crate::use_avx2() {
                    // SAFETY: the processor has AVX2 (`use_avx2` detected it).
                    return unsafe { avx2($($arg),*) };
                }
            }
            kernel($($arg),*)
        }
    };
}
