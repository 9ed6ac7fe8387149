"""The scene format's radiance along a camera ray, and the `point` image, read from the spec
(docs/scene-format.md: sunglint-scene/1, /2 and /3's moving camera; not the lattice
cascades) alone, in plain Python.

The format promises that "other renderers render the same files, pixel for pixel". This module
is such another renderer, written from the spec's text and nothing of sunglint's source, so
that spec_point_test.py can check the promise against `sunglint render -m point` (one sample
at each pixel centre at the display time t_f) instead of assuming it. It is slow and plain on
purpose, each step named after the part of the spec it follows, so that a graphics engineer
can hold one against the other.

Besides each pixel's value it reports how close the pixel-centre sample lies to a
discontinuity of the radiance (the light disk's rim, r.y = 0, the horizon) and whether its hit
is ill-conditioned (a ray grazing a displaced crest, or far water near the horizon), where two
correct renderers may differ by their rounding; the test leaves those few pixels out.
Standard library only.
"""
import math

R0 = 0.02  # Schlick's reflectance at normal incidence (the spec's value)
# What two correct renderers may differ by, for the conditioning test of a hit (hit_is_unstable):
HEIGHT_TOLERANCE = 1e-8      # m: the error of a displaced intersection in the water's height
DIRECTION_TOLERANCE = 1e-13  # rad: the rounding of a ray's direction (at s, s * this in height)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(v):
    n = math.sqrt(dot(v, v))
    return (v[0] / n, v[1] / n, v[2] / n)


def lerp(a, b, w):
    return tuple(a[c] + (b[c] - a[c]) * w for c in range(3))


def colour(x):
    """A radiance: a number (grey, the same in the three channels) or [r, g, b] (/2)."""
    if isinstance(x, (int, float)):
        return (float(x),) * 3
    return tuple(float(c) for c in x)


class Scene:
    """One parsed scene file (assumed valid: the test writes them; sunglint checks validity)."""

    def __init__(self, d):
        self.width, self.height = d["image"]["width"], d["image"]["height"]

        # Camera: position/look_at, or /3 keyframes; `up` and vfov_deg stay constant.
        cam = d["camera"]
        self.up = normalize(cam.get("up", [0, 1, 0]))
        vfov = math.radians(cam.get("vfov_deg", 40))
        self.tan_half_v = math.tan(vfov / 2)  # full vertical field of view
        self.tan_half_h = self.tan_half_v * self.width / self.height  # follows from the aspect
        if "keyframes" in cam:
            self.keys = [(float(k["time"]), tuple(map(float, k["position"])),
                          tuple(map(float, k["look_at"]))) for k in cam["keyframes"]]
        else:
            self.keys = [(0.0, tuple(map(float, cam["position"])),
                          tuple(map(float, cam["look_at"])))]

        # Light: a disk of directions of angular radius r around the unit `direction`.
        li = d["light"]
        self.light_dir = normalize(li["direction"])
        radius = math.radians(li["angular_radius_deg"])
        self.cos_radius, self.sin_radius = math.cos(radius), math.sin(radius)
        self.light = colour(li.get("radiance", 1.0))
        self.light_visible = bool(li.get("visible", False))

        # Sky: constant `radiance` (default 0), or /2's zenith/horizon gradient.
        sky = d.get("sky", {})
        self.gradient = "zenith" in sky
        if self.gradient:
            self.zenith, self.horizon = colour(sky["zenith"]), colour(sky["horizon"])
            self.exponent = float(sky.get("exponent", 0.5))
        else:
            self.sky_const = colour(sky.get("radiance", 0.0))

        # Water: h(x, z, t) = sum_i A_i sin(a_i x + b_i z + c_i t + phi_i).
        s = d["surface"]
        self.displaced = s.get("geometry", "flat") == "displaced"
        self.schlick = s.get("fresnel", "none") == "schlick"
        self.sea = colour(s.get("sea_radiance", 0.0))
        self.waves = [(float(w["amplitude"]), float(w["wave_vector"][0]),
                       float(w["wave_vector"][1]), float(w["angular_frequency"]),
                       float(w.get("phase", 0.0))) for w in s["waves"]]
        # Bounds for the displaced intersection: |h| <= A, |grad h| <= S, |second derivative| <= K2.
        self.amp_sum = sum(A for A, *_ in self.waves)
        self.slope_sum = sum(A * math.hypot(a, b) for A, a, b, _, _ in self.waves)
        self.curv_sum = sum(A * (a * a + b * b) for A, a, b, _, _ in self.waves)
        self.k_max = max([math.hypot(a, b) for _, a, b, _, _ in self.waves] + [1e-9])

        an = d.get("animation", {})
        self.t0, self.fps = float(an.get("t0", 0.0)), float(an.get("fps", 30))
        self.shutter = float(an.get("shutter", 1.0))  # the interval [t_f - shutter / fps, t_f]

    # ---- time and camera ----------------------------------------------------------------
    def display_time(self, frame):
        """Frame f (0-based) is displayed at t_f = t0 + f / fps."""
        return self.t0 + frame / self.fps

    def camera_at(self, t):
        """Position and look-at linearly interpolated between the keyframes around t, the first
        keyframe's values before it and the last one's after it; the basis from them and `up`."""
        k = self.keys
        if t <= k[0][0]:
            pos, look = k[0][1], k[0][2]
        elif t >= k[-1][0]:
            pos, look = k[-1][1], k[-1][2]
        else:
            n = max(i for i in range(len(k) - 1) if k[i][0] <= t)
            w = (t - k[n][0]) / (k[n + 1][0] - k[n][0])
            pos, look = lerp(k[n][1], k[n + 1][1], w), lerp(k[n][2], k[n + 1][2], w)
        forward = normalize(tuple(look[c] - pos[c] for c in range(3)))
        right = normalize(cross(forward, self.up))
        true_up = cross(right, forward)
        return pos, forward, right, true_up

    def ray(self, camera, x, y):
        """The ray through image-plane point (x, y): x in [0, width] to the right, y in
        [0, height] downwards (row 0 at the top). Pixel (i, j)'s centre is (i + 0.5, j + 0.5)."""
        pos, forward, right, true_up = camera
        u = (2 * x / self.width - 1) * self.tan_half_h
        v = (1 - 2 * y / self.height) * self.tan_half_v
        return pos, normalize(tuple(forward[c] + u * right[c] + v * true_up[c] for c in range(3)))

    # ---- water ---------------------------------------------------------------------------
    def water_height(self, x, z, t):
        return sum(A * math.sin(a * x + b * z + c * t + ph) for A, a, b, c, ph in self.waves)

    def water_normal(self, x, z, t):
        """normalize(-dh/dx, 1, -dh/dz), analytically."""
        gx = gz = 0.0
        for A, a, b, c, ph in self.waves:
            k = A * math.cos(a * x + b * z + c * t + ph)
            gx += k * a
            gz += k * b
        return normalize((-gx, 1.0, -gz))

    def hit(self, o, d, t, lift=0.0, s_from=0.0):
        """Step 1: the ray parameter s of the hit, None if the ray meets no water. `lift`
        raises the water by that much (for hit_is_unstable; the spec's hit has lift 0)."""
        if self.displaced:
            return self.first_hit_displaced(o, d, t, lift, s_from)
        return (lift - o[1]) / d[1] if d[1] < 0 else None  # the plane y = 0

    def first_hit_displaced(self, o, d, t, lift=0.0, s_from=0.0):
        """The first s >= s_from with o.y + s d.y = h(o + s d, t) + lift (None: the ray stays
        above the crests).

        f(s) = o.y + s d.y - h - lift, positive above the water. It is marched from where the
        ray enters the slab of the crests to where it leaves that of the troughs: far from the
        water in steps that cannot pass a root (f / its Lipschitz bound), near it in steps of
        1/24 of the shortest wavelength. Each step [a, b] is searched for its first root by a
        bisection made rigorous by the bound K on |f''|: f >= min(f(a), f(b)) - K (b - a)^2 / 8
        there, so a part whose ends both exceed that holds no root; other parts are halved,
        the left half first, down to the rounding of s."""
        if d[1] >= 0 and o[1] > self.amp_sum + lift:
            return None  # pointing up from above every crest: no water
        if d[1] >= 0:
            raise ValueError("camera below the wave crests")
        horiz = math.hypot(d[0], d[2])
        lipschitz = -d[1] + self.slope_sum * horiz
        curv = self.curv_sum * horiz * horiz
        min_step = (2 * math.pi / self.k_max) / 24 / max(horiz, 1e-12)
        s = max(s_from, (o[1] - lift - self.amp_sum) / -d[1])
        s_end = (o[1] - lift + self.amp_sum) / -d[1] + 1e-9
        waves = [(A, a, b, c * t + ph) for A, a, b, c, ph in self.waves]
        ox, oy, oz, dx, dy, dz = o[0], o[1] - lift, o[2], d[0], d[1], d[2]
        sin = math.sin

        def f(s):
            x, z = ox + s * dx, oz + s * dz
            return oy + s * dy - sum(A * sin(a * x + b * z + p) for A, a, b, p in waves)

        def first_root(a, fa, b, fb):
            parts = [(a, fa, b, fb)]
            while parts:
                a, fa, b, fb = parts.pop()
                h = b - a
                if fb > 0 and min(fa, fb) > curv * h * h / 8:
                    continue  # no root in [a, b]
                if h <= 4 * math.ulp(b):  # as fine as doubles go: the hit to rounding
                    if fb <= 0:
                        return b if fa > 0 else a
                    continue  # touches without crossing
                m = 0.5 * (a + b)
                fm = f(m)
                parts.append((m, fm, b, fb))
                parts.append((a, fa, m, fm))
            return None

        fs = f(s)
        if fs <= 0:
            return s
        while s < s_end:
            s2 = min(s + max(fs / lipschitz, min_step), s_end)
            f2 = f(s2)
            root = first_root(s, fs, s2, f2)
            if root is not None:
                return root
            s, fs = s2, f2
        raise ValueError("no hit above the troughs")

    # ---- radiance ------------------------------------------------------------------------
    def sky(self, d):
        """Constant, or horizon + (zenith - horizon) max(d.y, 0)^exponent."""
        if not self.gradient:
            return self.sky_const
        return lerp(self.horizon, self.zenith, max(d[1], 0.0) ** self.exponent)

    def rim_margin(self, r):
        """Angular distance (rad, to first order) of r from the light disk's rim."""
        return abs(dot(r, self.light_dir) - self.cos_radius) / self.sin_radius

    def shade_hit(self, o, d, s, t, notes=None):
        """Steps 3 and 4 at the hit o + s d."""
        x, z = o[0] + s * d[0], o[2] + s * d[2]
        n = self.water_normal(x, z, t)
        v = (-d[0], -d[1], -d[2])  # unit, towards the camera
        nv = dot(n, v)
        r = tuple(2 * nv * n[c] - v[c] for c in range(3))
        if notes is not None:
            notes.margins["reflection r.y = 0"] = abs(r[1])
        if r[1] <= 0:
            if notes is not None:
                notes.saw("sea")
            return self.sea
        fresnel = R0 + (1 - R0) * (1 - nv) ** 5 if self.schlick else 1.0
        in_disk = dot(r, self.light_dir) >= self.cos_radius
        if notes is not None:
            notes.margins["light disk rim"] = self.rim_margin(r)
            notes.saw("glint" if in_disk else "reflected sky")
        src = self.light if in_disk else self.sky(r)
        return tuple(fresnel * src[c] + (1 - fresnel) * self.sea[c] for c in range(3))

    def radiance(self, o, d, t, notes=None):
        """Radiance along the camera ray o + s d at time t (steps 1 to 4). `notes` (a Notes)
        receives what the ray saw, the sample's distance to each discontinuity near it, and
        whether its hit is unstable."""
        s = self.hit(o, d, t)
        if notes is not None:
            notes.margins["horizon"] = abs(d[1])  # water below, none (or a far hit) above
        if s is None:  # no water: the sky, or the light disk where light.visible
            if self.light_visible:
                in_disk = dot(d, self.light_dir) >= self.cos_radius
                if notes is not None:
                    notes.margins["light disk rim"] = self.rim_margin(d)
                    notes.saw("light" if in_disk else "sky")
                if in_disk:
                    return self.light
            elif notes is not None:
                notes.saw("sky")
            return self.sky(d)
        value = self.shade_hit(o, d, s, t, notes)
        if notes is not None:
            notes.unstable_hit = self.hit_is_unstable(o, d, t, s, value)
        return value

    def hit_is_unstable(self, o, d, t, s, value):
        """Whether the value changes by more than 1e-6 relative when the water is raised or
        lowered by what two correct renderers may differ by at this hit: HEIGHT_TOLERANCE (the
        intersection's) plus s * DIRECTION_TOLERANCE (a ray tilted by that much passes that
        much higher or lower there). The hit then moves along the ray by lift / sin(angle
        between the ray and the water), a long way for a ray that grazes a crest or the far
        water near the horizon; a crest grazed (hit or missed) by that little may go."""
        lift = HEIGHT_TOLERANCE + s * DIRECTION_TOLERANCE
        raised = self.hit(o, d, t, lift)  # before s
        lowered = self.hit(o, d, t, -lift, s_from=s)  # after s
        for s2 in (raised, lowered):
            other = self.shade_hit(o, d, s2, t)
            if any(abs(other[c] - value[c]) > 1e-6 * max(1.0, abs(value[c])) for c in range(3)):
                return True
        return False

    # ---- the point image -----------------------------------------------------------------
    def render_point(self, frame):
        """`point`: one sample at each pixel centre at t_f. Returns image[j][i] = (r, g, b),
        row j = 0 at the top, and notes[j][i] (a Notes per pixel)."""
        t = self.display_time(frame)
        camera = self.camera_at(t)
        image, notes = [], []
        for j in range(self.height):
            image.append([])
            notes.append([])
            for i in range(self.width):
                o, d = self.ray(camera, i + 0.5, j + 0.5)
                n = Notes()
                image[j].append(self.radiance(o, d, t, n))
                notes[j].append(n)
        return image, notes


class Notes:
    """What one sample saw (sky, light, sea, glint: the light disk mirrored, reflected sky),
    its margins: {discontinuity: distance} (sines of angles, radians for small ones), and
    whether its hit is unstable (Scene.hit_is_unstable)."""

    def __init__(self):
        self.seen, self.margins, self.unstable_hit = None, {}, False

    def saw(self, what):
        self.seen = what

