"""scipy-compatible quasi-Monte Carlo engines whose points come from stratum.

``stratum.qmc.Sobol``, ``Halton``, ``LatinHypercube`` and ``PoissonDisk`` are
subclasses of ``scipy.stats.qmc.QMCEngine`` with scipy's constructor arguments
and methods, so existing code switches by changing one import:

>>> from stratum import qmc                       # was: from scipy.stats import qmc
>>> x = qmc.Sobol(d=2, scramble=False).random_base2(m=3)
>>> qmc.discrepancy(x)                            # scipy's definitions, computed by stratum
0.013882107204861112

The constructions follow scipy's definitions (Sobol' with Joe-Kuo direction
numbers scrambled by LMS + digital shift, Halton scrambled by random digit
permutations, Latin hypercube, Bridson's Poisson disk), but the random streams
are stratum's counter-based ones: for the same seed the values differ from
scipy's. Unscrambled Sobol' points are bit-identical to scipy's; unscrambled
Halton points are correctly rounded, so they match scipy's (which sums
digits in floating point) to within 4 ulp, exactly in base 2.
Every difference is listed in docs/python-qmc.md.
"""
from __future__ import annotations

import copy
import inspect
import numbers
import os
import warnings

import numpy as np
from scipy.stats import qmc as _scipy_qmc

from . import InvalidArgument, _stratum
from . import points as _points
from . import samplers as _samplers

QMCEngine = _scipy_qmc.QMCEngine

# scipy's other public names (scale, discrepancy, MultivariateNormalQMC, ...)
# so that `from stratum import qmc` replaces `from scipy.stats import qmc`.
_OWN = ("Sobol", "Halton", "LatinHypercube", "PoissonDisk", "discrepancy", "update_discrepancy")
_REEXPORTED = [name for name in getattr(_scipy_qmc, "__all__", dir(_scipy_qmc))
               if not name.startswith("_") and name not in _OWN and hasattr(_scipy_qmc, name)]
globals().update({name: getattr(_scipy_qmc, name) for name in _REEXPORTED})
__all__ = sorted(set(_OWN) | set(_REEXPORTED) | {"QMCEngine"})

_MASK64 = (1 << 64) - 1
_MAX_THREADS = 1024
_OPTIMIZATIONS = ("random-cd", "lloyd")
# scipy <= 1.14 names the random-state argument `seed`, newer scipy `rng`.
_BASE_SEED_KEYWORD = "rng" if "rng" in inspect.signature(QMCEngine.__init__).parameters else "seed"


def _invalid(name, value, allowed):
    return InvalidArgument(f"invalid {name} = {value!r}: {allowed}")


def _integer(name, value, minimum=0, maximum=None, allowed=None):
    """An int (Python or numpy, not bool) in [minimum, maximum]."""
    if allowed is None:
        allowed = f"must be an integer >= {minimum}" if maximum is None else f"must be an integer in [{minimum}, {maximum}]"
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Integral, np.integer)):
        raise _invalid(name, value, allowed)
    value = int(value)
    if value < minimum or (maximum is not None and value > maximum):
        raise _invalid(name, value, allowed)
    return value


def _flag(name, value):
    """A bool (or numpy bool, or the integers 0 and 1)."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (numbers.Integral, np.integer)) and value in (0, 1):
        return bool(value)
    raise _invalid(name, value, "must be True or False")


def _sampler(name):
    for info in _samplers():
        if info["name"] == name:
            return info
    raise NotImplementedError(f"this stratum build has no registry sampler {name!r}; "
                              f"stratum.qmc needs it (see stratum.samplers())")


def _threads(workers):
    """scipy's `workers` (-1: every CPU) as a stratum thread count."""
    if isinstance(workers, (bool, np.bool_)) or not isinstance(workers, (numbers.Integral, np.integer)):
        raise _invalid("workers", workers, "must be -1 (every CPU) or a positive integer")
    workers = int(workers)
    if workers == -1:
        workers = os.cpu_count() or 1
    elif workers < 1:
        raise _invalid("workers", workers, "must be -1 (every CPU) or a positive integer")
    return min(workers, _MAX_THREADS)


def _mix(seed, counter):
    """A 64-bit seed for the counter-th draw of an engine (splitmix64 finalizer)."""
    z = (seed + (counter + 1) * 0x9E3779B97F4A7C15) & _MASK64
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _MASK64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _MASK64
    return z ^ (z >> 31)


def _is_generator(seed):
    return isinstance(seed, (np.random.Generator, np.random.RandomState))


def _draw_seed(generator):
    """One uniform 64-bit integer from a numpy Generator or RandomState."""
    if isinstance(generator, np.random.Generator):
        return int(generator.integers(0, 1 << 64, dtype=np.uint64))
    return int(generator.randint(0, 1 << 64, dtype=np.uint64))


def _resolve_seed(seed, rng):
    """scipy's seed (<= 1.14) or rng (newer) argument; both may not be given."""
    if rng is not None:
        if seed is not None:
            raise InvalidArgument("invalid seed and rng: give one of them (rng is the newer scipy name of seed)")
        seed = rng
    if seed is None or _is_generator(seed):
        return seed
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (numbers.Integral, np.integer)) or seed < 0:
        raise _invalid("seed", seed, "must be None, a non-negative integer or a numpy.random.Generator")
    return int(seed)


def _optimization(value):
    if value is None:
        return None
    if isinstance(value, str) and value.lower() in _OPTIMIZATIONS:
        return value.lower()
    raise _invalid("optimization", value, f"{value!r} is not a valid optimization method. It must be one of "
                   f"{set(_OPTIMIZATIONS)!r}")


def _sample_count(n):
    return _integer("n", n, 0, allowed="must be a non-negative integer")


class _Engine(QMCEngine):
    """What the four engines share: seeds, counting, optimization, integers."""

    _registry_name = ""

    def _check_d(self, d):
        """d = 0 is scipy's empty engine (samples of shape (n, 0)); otherwise the registry's range."""
        info = _sampler(self._registry_name)
        d = _integer("d", d, 0, allowed="d must be a non-negative integer value")
        if d > info["max_dim"]:
            raise _invalid("d", d, f"{self._too_many_dimensions(info['max_dim'])} "
                           f"({self._registry_name} supports d from {info['min_dim']} to {info['max_dim']})")
        return d

    def _too_many_dimensions(self, max_dim):
        return f"Maximum supported dimensionality is {max_dim}."

    def _setup(self, d, *, optimization, seed, rng):
        d = self._check_d(d)
        optimization = _optimization(optimization)
        seed = _resolve_seed(seed, rng)
        self._seed_argument = copy.deepcopy(seed)
        QMCEngine.__init__(self, d=d, optimization=optimization, **{_BASE_SEED_KEYWORD: seed})
        # The stratum seed: an integer seed is used as is (reduced to 64 bits
        # by numpy's SeedSequence when larger), a Generator gives one draw,
        # None gives fresh entropy (through the fresh Generator scipy made).
        if seed is None or _is_generator(seed):
            self._stratum_seed = _draw_seed(self.rng)
        elif seed <= _MASK64:
            self._stratum_seed = seed
        else:
            self._stratum_seed = int(np.random.SeedSequence(seed).generate_state(1, np.uint64)[0])
        self._optimization_name = optimization

    @property
    def stratum_seed(self):
        """The 64-bit seed handed to stratum's registry."""
        return self._stratum_seed

    def random(self, n=1, *, workers=1):
        """Draw `n` points in the half-open interval ``[0, 1)``.

        `workers` (-1: every CPU) is the number of threads; the values do not
        depend on it."""
        n = _sample_count(n)
        threads = _threads(workers)
        if n == 0 or self.d == 0:
            sample = np.empty((n, self.d))
        else:
            sample = self._random(n, workers=threads)
        if self.optimization_method is not None and len(sample) > 1:
            sample = self.optimization_method(sample)
        self.num_generated += len(sample)
        return sample

    def integers(self, l_bounds, *, u_bounds=None, n=1, endpoint=False, workers=1):
        """Draw `n` integers from `l_bounds` (inclusive) to `u_bounds`
        (exclusive; inclusive with endpoint=True) as floor(l + (u - l) x),
        like scipy. With u_bounds=None the range is [0, l_bounds)."""
        if u_bounds is None:
            u_bounds, l_bounds = l_bounds, 0
        lower, upper = np.atleast_1d(l_bounds), np.atleast_1d(u_bounds)
        for name, value in (("l_bounds", lower), ("u_bounds", upper)):
            if not np.issubdtype(value.dtype, np.integer):
                raise _invalid(name, value.tolist(), "must be an integer or an array-like of integers")
        if _flag("endpoint", endpoint):
            upper = upper + 1
        try:
            lower, upper = np.broadcast_to(lower, self.d), np.broadcast_to(upper, self.d)
        except ValueError:
            raise _invalid("l_bounds", lower.tolist(), f"l_bounds and u_bounds must broadcast to d = {self.d}") from None
        if not np.all(lower < upper):
            raise _invalid("u_bounds", np.asarray(u_bounds).tolist(), "must be above l_bounds everywhere")
        sample = self.random(n, workers=workers)
        return np.floor(_scipy_qmc.scale(sample, lower, upper)).astype(np.int64)

    def reset(self):
        """Back to the state after construction: the same points again."""
        seed = copy.deepcopy(self._seed_argument)
        self.rng = seed if _is_generator(seed) else np.random.default_rng(seed)
        if _is_generator(seed):
            _draw_seed(self.rng)  # the draw that made the stratum seed, so the optimizer's stream repeats too
        if hasattr(self, "rng_seed"):
            self.rng_seed = copy.deepcopy(self._seed_argument)
        self._rebuild_optimizer()
        self.num_generated = 0
        return self

    def _rebuild_optimizer(self):
        if self._optimization_name is None:
            return
        # scipy binds the optimizer to self.rng at construction; rebind it.
        keywords = dict(getattr(self.optimization_method, "keywords", {}))
        if "rng" in keywords:
            keywords["rng"] = self.rng
            self.optimization_method = type(self.optimization_method)(self.optimization_method.func, **keywords)

    def fast_forward(self, n):
        """Skip `n` points: the next draw continues as if they had been drawn."""
        self.num_generated += _integer("n", n, 0, allowed="must be a non-negative integer")
        return self


class _Sequence(_Engine):
    """An index-addressable registry sequence: point i depends only on the
    seed and i, so the engine's position is the registry's start index."""

    def _setup_sequence(self, d, randomize, scramble, scrambled_name, *, optimization, seed, rng):
        d = self._check_d(d)
        self.scramble = _flag("scramble", scramble)
        accepted = _sampler(self._registry_name)["randomizers"]
        if randomize is None:
            randomize = scrambled_name if self.scramble else "none"
            if randomize not in accepted:
                raise _invalid("scramble", self.scramble, f"this build's {self._registry_name} has no {randomize!r} "
                               "randomizer (it accepts " + ", ".join(accepted) + ")")
        elif randomize not in accepted:
            raise _invalid("randomize", randomize, f"{self._registry_name} accepts " + ", ".join(accepted))
        self.randomize = randomize
        self._setup(d, optimization=optimization, seed=seed, rng=rng)

    _params = {}

    def _draw(self, n, start, threads):
        return _points(self._registry_name, n, self.d, seed=self._stratum_seed, randomize=self.randomize,
                       start=start, threads=threads, **self._params)

    def _random(self, n=1, *, workers=1):
        return self._draw(n, self.num_generated, workers)


class Sobol(_Sequence):
    """Sobol' sequence (Joe-Kuo direction numbers) from stratum's registry.

    Same arguments as ``scipy.stats.qmc.Sobol``: scramble=True is a linear
    matrix scramble plus digital shift (LMS + shift); scramble=False is the
    plain sequence, identical to scipy's. bits (default 30, as scipy) sets
    the resolution of the output (multiples of 2**-bits) and the most points
    the engine hands out (2**bits). `seed` (or its newer scipy name `rng`)
    is None, an integer or a numpy Generator.

    stratum extension: randomize= picks any randomizer of the "sobol" registry
    entry ("lms", "owen", "owen-hash", "none", ...); it overrides scramble.
    """

    _registry_name = "sobol"
    _params = {"order": "gray"}  # scipy's order: point i is C · (i XOR i/2)

    class _MaxDim:
        def __get__(self, instance, owner):
            return _sampler("sobol")["max_dim"]

    MAXDIM = _MaxDim()

    def __init__(self, d, *, scramble=True, bits=None, seed=None, optimization=None, rng=None, randomize=None):
        bits = 30 if bits is None else _integer("bits", bits, 1, 64, "Maximum supported 'bits' is 64 (bits must be an integer in [1, 64])")
        self.bits = bits
        self.maxn = 2**bits
        self._setup_sequence(d, randomize, scramble, "lms", optimization=optimization, seed=seed, rng=rng)
        self._init_quad = {"d": self.d, "scramble": True, "bits": bits, "optimization": self._optimization_name,
                           "randomize": None if randomize == "none" else randomize}

    def _check_capacity(self, n):
        total = self.num_generated + n
        if total > self.maxn:
            raise _invalid("n", n, f"At most 2**{self.bits}={self.maxn} distinct points can be generated. "
                           f"{self.num_generated} points have been previously generated, then: "
                           f"n={self.num_generated}+{n}={total}. "
                           + ("Consider increasing `bits`." if self.bits != 64 else ""))

    def random(self, n=1, *, workers=1):
        n = _sample_count(n)
        self._check_capacity(n)
        if self.num_generated == 0 and n & (n - 1) != 0:
            warnings.warn("The balance properties of Sobol' points require n to be a power of 2.", stacklevel=2)
        return super().random(n, workers=workers)

    def _draw(self, n, start, threads):
        # Keep `bits` binary digits, as scipy's bits-wide generator does (the
        # registry's bits parameter, done as the points are written); for LMS
        # and Owen scrambling this is the same scramble on `bits` digits.
        return _points(self._registry_name, n, self.d, seed=self._stratum_seed, randomize=self.randomize,
                       start=start, threads=threads, bits=self.bits, **self._params)

    def random_base2(self, m):
        """Draw n = 2**m points; the total drawn so far must stay a power of 2."""
        m = _integer("m", m, 0, 64, "must be an integer in [0, 64]")
        n = 2**m
        total = self.num_generated + n
        if total & (total - 1) != 0:
            raise _invalid("m", m, "The balance properties of Sobol' points require n to be a power of 2. "
                           f"{self.num_generated} points have been previously generated, then: "
                           f"n={self.num_generated}+2**{m}={total}. If you still want to do this, "
                           "the function 'Sobol.random()' can be used.")
        return self.random(n)


class Halton(_Sequence):
    """Halton sequence from stratum's registry.

    Same arguments as ``scipy.stats.qmc.Halton``: scramble=True applies random
    digit permutations (Owen 2017, scipy's scrambling); scramble=False is the
    plain sequence, correctly rounded (scipy's is within 4 ulp of it).

    stratum extension: randomize= picks any randomizer of the "halton"
    registry entry; it overrides scramble.
    """

    _registry_name = "halton"

    def __init__(self, d, *, scramble=True, optimization=None, seed=None, rng=None, randomize=None):
        self._setup_sequence(d, randomize, scramble, "permute", optimization=optimization, seed=seed, rng=rng)
        self._init_quad = {"d": self.d, "scramble": True, "optimization": self._optimization_name,
                           "randomize": None if randomize == "none" else randomize}


class CenteredDeprecationWarning(DeprecationWarning, UserWarning):
    """LatinHypercube(centered=True): scipy 1.10 warns with a UserWarning
    (the keyword went away in scipy 1.12); this class is both, so filters and
    pytest.warns for either category catch it."""


def _is_prime(p):
    return p >= 2 and all(p % k for k in range(2, int(p**0.5) + 1))


class LatinHypercube(_Engine):
    """Latin hypercube (N-rooks) designs from the registry's "n-rooks".

    Same arguments as ``scipy.stats.qmc.LatinHypercube``: each random(n) is
    a fresh design of n points, one in every [j/n, (j+1)/n) of every
    coordinate; scramble=False (or the older, deprecated centered=True) puts
    the points at the centres of their cells. strength=2 is the
    orthogonal-array based LHS (Tang 1993, "Orthogonal array-based Latin
    hypercubes"): n = p**2 for a prime p, d <= p + 1, and every pair of
    coordinates also puts one point in each of the p x p cells.
    """

    _registry_name = "n-rooks"

    def __init__(self, d, *, centered=False, scramble=True, strength=1, optimization=None, seed=None, rng=None):
        if _flag("centered", centered):
            warnings.warn("'centered' is deprecated and will be removed in SciPy 1.12. Please use 'scramble' "
                          "instead. 'centered=True' corresponds to 'scramble=False'.",
                          CenteredDeprecationWarning, stacklevel=2)
        self.scramble = _flag("scramble", scramble) and not centered
        if isinstance(strength, (bool, np.bool_)) or strength not in (1, 2):
            raise _invalid("strength", strength, f"{strength!r} is not a valid strength. It must be one of {{1, 2}}")
        self.strength = int(strength)
        self._setup(d, optimization=optimization, seed=seed, rng=rng)
        self._init_quad = {"d": self.d, "scramble": True, "strength": self.strength,
                           "optimization": self._optimization_name}

    def _design_seed(self):
        # Design k is seeded by (seed, points drawn before it); the first one
        # uses the seed itself, so it equals stratum.points("n-rooks", n, d, seed).
        return self._stratum_seed if self.num_generated == 0 else _mix(self._stratum_seed, self.num_generated)

    def _random(self, n=1, *, workers=1):
        if self.strength == 2:
            return self._orthogonal_array_lhs(n)
        params = {} if self.scramble else {"centered": 1}
        return _points(self._registry_name, n, self.d, seed=self._design_seed(), threads=workers, **params)

    def _orthogonal_array_lhs(self, n):
        """Tang (1993): the strength-2 orthogonal array OA(p^2, p+1, p, 2) of
        Bush (columns a, b, a + k b mod p), its symbols permuted at random per
        column, each symbol's p rows spread over the p sub-cells by a random
        Latin hypercube (at the sub-cell centres when scramble=False)."""
        p = int(np.sqrt(n))
        while (p + 1) ** 2 <= n:
            p += 1
        if p * p != n or not _is_prime(p):
            below = [q for q in range(max(p, 2), 1, -1) if _is_prime(q)][:1]
            above = next(q for q in range(p + 1, 2 * p + 3) if _is_prime(q))
            close = [q * q for q in below + [above]]
            raise _invalid("n", n, f"n is not the square of a prime number. Close values are {close}")
        if self.d > p + 1:
            raise _invalid("n", n, f"n is too small for d. Must be n > (d-1)**2 (d = {self.d})")
        rng = np.random.default_rng(self._design_seed())
        a, b = np.divmod(np.arange(n), p)
        columns = [a, b] + [(a + k * b) % p for k in range(1, p)][: max(self.d - 2, 0)]
        sample = np.empty((n, self.d))
        for j in range(self.d):
            symbols = rng.permutation(p)[columns[j]]
            order = np.argsort(symbols, kind="stable")  # the p rows of symbol 0, then of symbol 1, ...
            sub_cells = np.argsort(rng.random((p, p)), axis=1).ravel()  # a random permutation per symbol
            jitter = rng.random(n) if self.scramble else np.full(n, 0.5)
            sample[order, j] = (symbols[order] * p + sub_cells + jitter) / n
        return sample


class PoissonDisk(_Engine):
    """Poisson-disk points (Bridson 2007) from the registry's "poisson-disk".

    Same arguments as ``scipy.stats.qmc.PoissonDisk`` (radius, ncandidates,
    hypersphere="volume"): random(n) hands out the next n points of one
    maximal set whose points are at least `radius` apart, fewer when the set
    is exhausted; fill_space() returns every point left.

    stratum extension: periodic=True measures distances on the torus.
    """

    _registry_name = "poisson-disk"

    def __init__(self, d, *, radius=0.05, hypersphere="volume", ncandidates=30, optimization=None, seed=None,
                 rng=None, periodic=False):
        if isinstance(radius, (bool, np.bool_)) or not isinstance(radius, (numbers.Real, np.floating, np.integer)) \
                or not 0 < float(radius) <= 1:
            raise _invalid("radius", radius, "must be a number in (0, 1]")
        if hypersphere not in ("volume", "surface"):
            raise _invalid("hypersphere", hypersphere, f"{hypersphere!r} is not a valid hypersphere sampling method. "
                           "It must be one of {'volume', 'surface'}")
        if hypersphere == "surface" and periodic:
            raise _invalid("periodic", periodic, "periodic=True is available with hypersphere='volume' only")
        self.radius = float(radius)
        self.hypersphere = hypersphere
        self.ncandidates = _integer("ncandidates", ncandidates, 1, allowed="must be a positive integer")
        self.periodic = _flag("periodic", periodic)
        self._setup(d, optimization=optimization, seed=seed, rng=rng)
        self._maximal = None
        self._init_quad = {"d": self.d, "radius": self.radius, "hypersphere": hypersphere,
                           "ncandidates": self.ncandidates, "optimization": self._optimization_name,
                           "periodic": self.periodic}

    def _maximal_set(self, threads):
        if self._maximal is None and self.hypersphere == "surface":
            self._maximal = _surface_poisson_disk(self.d, self.radius, self.ncandidates, self._stratum_seed)
        if self._maximal is None:
            params = {"candidates": self.ncandidates}
            if self.periodic:
                params["periodic"] = 1
            self._maximal = _points(self._registry_name, None, self.d, seed=self._stratum_seed, radius=self.radius,
                                    threads=threads, **params)
        return self._maximal

    def _random(self, n=1, *, workers=1):
        maximal = self._maximal_set(workers)
        return maximal[self.num_generated:self.num_generated + n].copy()

    def fill_space(self):
        """Every point of the maximal set not yet handed out."""
        remaining = len(self._maximal_set(1)) - self.num_generated
        return self.random(max(remaining, 0))

    def fast_forward(self, n):
        n = _integer("n", n, 0, allowed="must be a non-negative integer")
        self.num_generated = min(self.num_generated + n, len(self._maximal_set(1)))
        return self


def _surface_poisson_disk(d, radius, candidates, seed):
    """Bridson (2007), "Fast Poisson disk sampling in arbitrary dimensions",
    with scipy's hypersphere="surface" candidates: uniform on the sphere of
    radius 1.001 r around the active point. A background grid of cells of
    side r / sqrt(d) holds at most one point each; the neighbours of a
    candidate are within ceil(sqrt(d)) cells. Points in generation order."""
    rng = np.random.default_rng(seed)
    cell = radius / np.sqrt(d)
    size = int(np.ceil(1 / cell))
    if size**d > 1 << 26:
        raise _invalid("radius", radius, f"too small for hypersphere='surface' in d = {d} (background grid of "
                       f"{size}^{d} cells; at most 2^26)")
    reach = int(np.ceil(np.sqrt(d)))
    offsets = np.stack(np.meshgrid(*[np.arange(-reach, reach + 1)] * d, indexing="ij"), -1).reshape(-1, d)
    strides = size ** np.arange(d)[::-1]
    grid = np.full(size**d, -1, dtype=np.int64)
    points = [rng.random(d)]
    grid[np.dot(np.minimum((points[0] / cell).astype(np.int64), size - 1), strides)] = 0
    active = [0]
    while active:
        k = int(rng.integers(len(active)))
        directions = rng.standard_normal((candidates, d))
        trial = points[active[k]] + 1.001 * radius * directions / np.linalg.norm(directions, axis=1)[:, None]
        accepted = False
        for x in trial[np.all((trial >= 0) & (trial < 1), axis=1)]:
            home = np.minimum((x / cell).astype(np.int64), size - 1)
            cells = home + offsets
            cells = cells[np.all((cells >= 0) & (cells < size), axis=1)]
            near = grid[cells @ strides]
            near = near[near >= 0]
            if len(near) and np.min(np.sum((np.asarray([points[i] for i in near]) - x) ** 2, axis=1)) < radius**2:
                continue
            grid[home @ strides] = len(points)
            active.append(len(points))
            points.append(x)
            accepted = True
        if not accepted:
            active[k] = active[-1]
            active.pop()
    return np.asarray(points).reshape(-1, d)


_DISCREPANCY_METHODS = ("CD", "WD", "MD", "L2-star")


def _unit_sample(sample, name, label, ndim):
    """sample as C-ordered float64 with scipy's checks and messages (which the
    stratum messages extend with the position of the first bad coordinate)."""
    array = np.asarray(sample, dtype=np.float64, order="C")
    if array.ndim != ndim:
        raise InvalidArgument(f"invalid {name} = array of shape {array.shape}: {label} is not a {ndim}D array")
    if array.size == 0:
        raise InvalidArgument(f"invalid {name} = array of shape {array.shape}: {label} is empty")
    bad = np.argwhere(~(np.isfinite(array) & (array >= 0) & (array <= 1)))
    if len(bad):
        where = "".join(f"[{i}]" for i in bad[0])
        raise InvalidArgument(f"invalid {name}{where} = {array[tuple(bad[0])]!r}: {label} is not in unit hypercube "
                              "(coordinates must be finite and in [0, 1])")
    return array


def _discrepancy_workers(workers):
    """scipy's _validate_workers, with its messages."""
    if isinstance(workers, (bool, np.bool_)) or not isinstance(workers, (numbers.Integral, np.integer)):
        raise _invalid("workers", workers, "must be -1 (every CPU) or a positive integer")
    workers = int(workers)
    if workers == -1:
        workers = os.cpu_count()
        if workers is None:
            raise NotImplementedError("Cannot determine the number of cpus using os.cpu_count(), "
                                      "cannot use -1 for the number of workers")
    elif workers <= 0:
        raise _invalid("workers", workers, f"Invalid number of workers: {workers}, must be -1 or > 0")
    return workers


def discrepancy(sample, *, iterative=False, method="CD", workers=1):
    """scipy.stats.qmc.discrepancy, computed by stratum (same signature and values).

    Returns the SQUARED centered ("CD"), wrap-around ("WD") and mixture ("MD")
    discrepancies and the L2-star discrepancy itself ("L2-star"), exactly as
    scipy does; ``iterative=True`` normalizes by n + 1 for update_discrepancy.
    The pair sums use stratum's kernels: O(N log N) (d = 2) or O(N log^2 N)
    (d = 3) for L2-star, vectorized O(d N^2) over ``workers`` threads otherwise;
    the value does not depend on ``workers``. Accuracy: each value is a small
    difference of O(1) sums, and stratum accumulates in long double; against
    a reference exact to 2e-16 (bench/qmc_discrepancy_accuracy.py: n = 256 to
    4096, d = 2 and 5, random and scrambled Sobol' points) its error is at most
    1e-15 absolute, 9e-13 relative for random points and 1.6e-9 for Sobol'
    points (whose squared discrepancy is as small as 1e-7), while scipy's,
    summed in double, grows with n: up to 1.3e-9 (random) and 2e-7 (Sobol')
    relative at n = 1024, 3.3e-8 and 3.7e-6 at n = 4096: at n >= 1024 from 10x
    to over 10^4x stratum's. The two therefore agree only to within scipy's
    error; where they differ, stratum is the accurate one. Differences from
    scipy: NaN and Inf are rejected (scipy returns nan), and messages name the first bad coordinate.
    For the discrepancy itself of every method (not squared) see
    ``stratum.measure``; docs/discrepancy.md.
    """
    array = _unit_sample(sample, "sample", "Sample", 2)
    workers = _discrepancy_workers(workers)
    if not isinstance(method, str) or method not in _DISCREPANCY_METHODS:
        raise InvalidArgument(f"invalid method = {method!r}: {method!r} is not a valid method. It must be one of "
                              f"{set(_DISCREPANCY_METHODS)!r}")
    # The value does not depend on the thread count: more threads than CPUs would only oversubscribe.
    return _stratum.scipy_discrepancy(array, method, bool(iterative), min(workers, os.cpu_count() or 1, _MAX_THREADS))


def update_discrepancy(x_new, sample, initial_disc):
    """scipy.stats.qmc.update_discrepancy, computed by stratum in O(n d).

    The SQUARED centered discrepancy of `sample` with `x_new` appended, given
    ``initial_disc = discrepancy(sample, iterative=True)`` (method "CD").
    """
    array = _unit_sample(sample, "sample", "Sample", 2)
    point = _unit_sample(x_new, "x_new", "x_new", 1)
    if point.shape[0] != array.shape[1]:
        raise InvalidArgument(f"invalid x_new = array of shape {point.shape}: x_new and sample must be broadcastable "
                              f"(sample has d = {array.shape[1]})")
    return _stratum.update_centered_discrepancy(point, array, float(initial_disc))
