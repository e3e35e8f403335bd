"""Inertia rules that need the geometry or the whole model (warnings; `lint` and `inertia`).

They are not part of `check`, which stays a drop-in for check_urdf. The tensor a
link's geometry implies comes from :mod:`urdfcli.inertia`.
"""

from __future__ import annotations

import math
from collections import Counter, defaultdict
from typing import TYPE_CHECKING, NamedTuple

from ..diagnostics import Fix
from ..model import inertia as model
from ..model import massprops
from ..model.inertia import OVERREACH, Assessment, axes_apart, declared_body, reach
from ..model.kinematics import roots, walk
from ..model.massprops import number, tensor_text
from ..model.numbers import format_number
from ..model.poses import zero_poses
from ..model.units import is_dot, mis_scaled
from ..read.memo import once
from .base import INFO, UNSAFE, WARNING, Kind, Option, Remedy, RuleSet, check
from .physics import absorbed, invalid_tensors

if TYPE_CHECKING:
    from ..model.load import Loaded

ROOT_MASS = 0.001  # kg: a lighter root is the usual answer to KDL's complaint
SIZE_RATIO = 2.0  # links this many times apart in mass or size cannot share one honest tensor
TOLERANCE = Option(
    "tolerance",
    massprops.TOLERANCE,
    "How close two tensors must be to match (largest element difference, relative to the larger's largest element): "
    "a shared tensor that fits each link's geometry, principal moments that match the geometry's. "
    "0.1 lets values rounded to two digits pass.",
)
DENSITY = Option("density", 0.0, "kg/m³: when positive, masses come from the geometry's volume instead of the declared mass.")


def _names(links) -> str:
    """'a', 'b' and 'c': every name, so that each link is found in the message."""
    quoted = [f"'{link.name}'" for link in links]
    return quoted[0] if len(quoted) == 1 else f"{', '.join(quoted[:-1])} and {quoted[-1]}"


def _naming(links) -> str:
    return f"{'link' if len(links) == 1 else 'links'} {_names(links)}"


def _declaring(loaded):
    """Links with positive mass and a tensor (frame links and broken inertials left out)."""
    for link in loaded.robot.links.values():
        inertial = link.inertial
        if inertial is not None and inertial.inertia and (inertial.mass or 0) > 0:
            yield link


def _assess(loaded, link, options):
    return model.assess(loaded, link, options.get("density") or None)


def written_alike(loaded) -> dict[str, tuple]:
    """Each declaring link's name -> what the geometry rules judge it by, as it was read:
    its inertial's values and its shapes' (each value the very object the reader made of
    its text: links that write the same texts share them) and which meshes are in a wrong
    unit. Links alike in all of it are judged once: the fingers of a hand, the wheels of
    a base, a generated chain (three in ten of the published models' links). Each rule
    works it out again rather than keeping it with the model: kept, it would hold some
    hundred bytes a link for as long as the model is open."""
    skipped = mis_scaled(loaded)
    found = {}
    for link in _declaring(loaded):
        inertial = link.inertial
        found[link.name] = (
            inertial.mass, id(inertial.origin), id(inertial.inertia),
            tuple(_shape_as_read(shape, skipped) for shape in link.visuals), tuple(_shape_as_read(shape, skipped) for shape in link.collisions),
        )
    return found


def _shape_as_read(shape, skipped: set[int]) -> tuple | None:
    geometry = shape.geometry
    if geometry is None:
        return None
    return (id(shape.origin), geometry.kind, id(geometry.size), id(geometry.radius), id(geometry.length), geometry.filename, id(geometry.scale), shape.at in skipped)


def _implies(found) -> str | None:
    return f"its {found.implied.source} implies {tensor_text(found.expected)}" if found and found.expected else None


@check("I007", "placeholder-identity", WARNING, "An inertia tensor that is the identity: a placeholder.", rule_set=RuleSet.LINT, options=(TOLERANCE,), kind=Kind.MASS, remedy=Remedy.INERTIAL, fix=UNSAFE)
def placeholder_identity(loaded, given):
    """## What it does
    Flags ``ixx=iyy=izz=1`` without products of inertia, unless the link's geometry really
    implies it; links sharing this placeholder are named in one diagnostic, at the first
    of them. I008 and I009 leave these links to it. Links lighter than 20 g fixed to a
    heavier body are left alone.

    ## Why is this bad?
    The identity is what gets typed when the real value is unknown. On a 100 kg
    beam 20 m long it is off by a factor of three thousand: the simulated beam
    swings like a feather.

    ## Example
    ```xml
    <link name="beam">
      <collision><geometry><box size="1 1 20"/></geometry></collision>
      <inertial>
        <mass value="100"/>
        <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>
      </inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="beam">
      <collision><geometry><box size="1 1 20"/></geometry></collision>
      <inertial>
        <mass value="100"/>
        <inertia ixx="3341.67" ixy="0" ixz="0" iyy="3341.67" iyz="0" izz="16.6667"/>
      </inertial>
    </link>
    ```
    `urdfcli inertia --suggest` prints the values for each link.
    """
    links = identity_links(loaded, given.options)
    if len(links) == 1:
        yield loaded.diagnostic(
            "I007", f"inertia of link '{links[0].name}' is the identity, a placeholder", links[0].inertial.inertia_at,
            _implies(_assess(loaded, links[0], given.options)), subjects=(links[0].name,),
        )
    elif links:  # one cause: one diagnostic naming every link, at the first
        yield loaded.diagnostic(
            "I007",
            f"inertia of {len(links)} links is the identity, a placeholder: {_names(links)}",
            links[0].inertial.inertia_at,
            "`urdfcli inertia --suggest` prints the values each link's geometry implies",
            subjects=tuple(link.name for link in links),
        )


def identity_links(loaded, options) -> list:
    """Links whose tensor is the identity, unless their geometry really implies it."""
    found = []
    for link in _declaring(loaded):
        if massprops.is_identity(model.declared_tensor(link)) and not absorbed(loaded, link):
            assessment = _assess(loaded, link, options)
            if assessment is not None and assessment.expected is not None and not assessment.off(options["tolerance"]):
                continue
            found.append(link)
    return found


@check("I008", "placeholder-repeated", WARNING, "The same inertia tensor on links of very different sizes.", rule_set=RuleSet.LINT, options=(TOLERANCE,), kind=Kind.MASS, remedy=Remedy.INERTIAL, fix=UNSAFE)
def placeholder_repeated(loaded, given):
    """## What it does
    Flags a tensor repeated on links whose masses or geometries differ by more than a
    factor of two: one diagnostic per tensor, naming the links it does not fit, at the
    first of them. A link it fits (its geometry gives the tensor within ``tolerance``, or
    its largest moment is within three times of the uniform body filling its shapes, as a
    CAD tensor is) is the part the tensor was computed for, and is not named: PR2's caster
    wheels (0.44 kg) carry the tensor of their 3.47 kg caster body, and the diagnostic is
    about the wheels alone.
    Left alone: copies of one part (the same shapes: I012 compares their masses), links
    lighter than 20 g whose tensor adds nothing material to the body they are fixed to
    (dummy and frame links), zero tensors (I004), the identity (I007) and tensors no body
    can have (I005, I006), which their own rules report.

    ## Why is this bad?
    One small value pasted on every sensor and caster is a placeholder: a 35 g
    camera and a 125 g lidar cannot share an inertia. Identical wheels sharing one
    tensor are fine and are not flagged.

    ## Example
    ```xml
    <link name="laser">
      <collision><geometry><cylinder radius="0.04" length="0.04"/></geometry></collision>
      <inertial><mass value="0.125"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
    </link>
    <link name="camera_link">
      <collision><geometry><box size="0.015 0.13 0.022"/></geometry></collision>
      <inertial><mass value="0.035"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="laser">
      <collision><geometry><cylinder radius="0.04" length="0.04"/></geometry></collision>
      <inertial><mass value="0.125"/><inertia ixx="6.66667e-05" ixy="0" ixz="0" iyy="6.66667e-05" iyz="0" izz="0.0001"/></inertial>
    </link>
    <link name="camera_link">
      <collision><geometry><box size="0.015 0.13 0.022"/></geometry></collision>
      <inertial><mass value="0.035"/><inertia ixx="5.0703e-05" ixy="0" ixz="0" iyy="2.06792e-06" iyz="0" izz="4.99479e-05"/></inertial>
    </link>
    ```
    """
    for tensor, wrong, others in placeholder_groups(loaded, given.options):
        masses = [link.inertial.mass for link in wrong + others]
        if others:  # the tensor of a part, copied onto parts it does not fit: only those are named
            copied = f"{len(others)} other link{'s' if len(others) > 1 else ''} ({_weights(others)}), whose geometry gives it"
            message = (f"{_naming(wrong)} ({_weights(wrong)}) {'has' if len(wrong) == 1 else 'have'} the inertia tensor ({tensor_text(tensor)}) "
                       f"of {copied}: a copy, not {'its' if len(wrong) == 1 else 'their'} own")
        else:
            differ = (f"though they weigh {format_number(min(masses))} to {format_number(max(masses))} kg" if max(masses) > SIZE_RATIO * min(masses)
                      else "though their geometries differ in size")
            message = f"{_naming(wrong)} share one inertia tensor ({tensor_text(tensor)}), {differ}: a placeholder"
        yield loaded.diagnostic(
            "I008", message, wrong[0].inertial.inertia_at,
            "`urdfcli inertia --suggest` prints the values each link's geometry implies",
            subjects=tuple(link.name for link in wrong),
        )


def _weights(links) -> str:
    masses = sorted({link.inertial.mass for link in links})
    return f"{format_number(masses[0])} kg" if len(masses) == 1 else f"{format_number(masses[0])} to {format_number(masses[-1])} kg"


def placeholder_groups(loaded, options) -> list:
    """(tensor, links, others) for each tensor pasted on links of very different mass or size:
    the links whose own geometry does not give it, and those it fits; worked out once."""
    return once(loaded, _groups_within, options["tolerance"])


def _groups_within(loaded, tolerance: float) -> list:
    return _placeholder_groups(loaded, {"tolerance": tolerance})


def _placeholder_groups(loaded, options) -> list:
    groups = defaultdict(list)
    invalid = _invalid(loaded)
    for link in _declaring(loaded):
        tensor = model.declared_tensor(link)
        # light frames lost in their bodies draw nothing; the identity is I007's
        if (
            not absorbed(loaded, link) and not massprops.is_negligible(tensor)
            and not massprops.is_identity(tensor) and link.name not in invalid  # I007, I005 and I006 say it
        ):
            groups[tensor].append(link)
    found = []
    for tensor, links in groups.items():
        if len(links) < 2 or len({geometry_signature(link) for link in links}) == 1:
            continue  # one link, or copies of one part: same geometry and tensor (I012 compares their masses)
        assessed = {link.name: _assess(loaded, link, options) for link in links}
        sizes = [massprops.scale_of(a.expected) for a in assessed.values() if a is not None and a.expected is not None]
        masses = [link.inertial.mass for link in links]
        if max(masses) <= SIZE_RATIO * min(masses) and (len(sizes) < 2 or max(sizes) <= SIZE_RATIO * min(sizes)):
            continue
        wrong = [link for link in links if not _fits(assessed[link.name], options["tolerance"])]
        if wrong:
            found.append((tensor, wrong, [link for link in links if link not in wrong]))
    return found


CAD_RANGE = 3.0  # a CAD tensor is within this factor of the uniform body filling the part's shapes


def _fits(found, tolerance: float) -> bool:
    """Whether a shared tensor is the link's own: its geometry gives it within the tolerance,
    or its largest moment is within CAD_RANGE of the uniform body's (the part it was computed for)."""
    if found is None or found.expected is None or massprops.is_zero(found.expected):
        return False
    if not found.off(tolerance):
        return True
    declared, expected = massprops.principal_moments(found.declared)[2], massprops.principal_moments(found.expected)[2]
    return expected / CAD_RANGE <= declared <= expected * CAD_RANGE


def geometry_signature(link) -> tuple:
    """What a link's shapes are, wherever they stand: the collision shapes (else the visual
    shapes) by kind, mesh file, scale and size, placeholder dots left out (they say nothing
    of the part). Two copies of one part (left and right finger, four wheels) have the same."""
    shapes = _sized(link.collisions) or _sized(link.visuals)
    return tuple(sorted((g.kind, g.filename or "", g.scale, g.size or (), g.radius or 0.0, g.length or 0.0) for g in (s.geometry for s in shapes)))


def _sized(shapes) -> list:
    return [s for s in shapes if s.geometry is not None and not is_dot(s.geometry)]


MIRROR_RATIO = 5.0  # copies of one part this many times apart in mass: one mass is wrong


@check("I012", "copies-differ-in-mass", WARNING, "Two links with the same geometry and inertia tensor whose masses are five or more times apart.", rule_set=RuleSet.LINT, kind=Kind.MASS, remedy=Remedy.INERTIAL)
def copies_differ_in_mass(loaded, given):
    """## What it does
    Flags links that are copies of one part, the same shapes (by kind, mesh file, scale
    and size, wherever they stand) and the same inertia tensor, when their masses are five
    or more times apart: left and right fingers, the wheels of a base. Names the links, at
    the lightest and the heaviest. Links without shapes, with a zero tensor (frames) or
    within five times of each other are left alone; placeholder dots (2 cm or less in
    every direction, as the 1 µm collision cylinder uuv_simulator's sensors carry) are not
    shapes: such a link is compared by its visuals.

    ## Why is this bad?
    One part has one mass: a tensor copied with the shapes, and a mass typed again with a
    decimal point out of place (moveit_resources' Panda: `panda_rightfinger` 0.15 kg,
    `panda_leftfinger` 0.015 kg). The simulated fingers close at different speeds and the
    controller's model is wrong for one of them.

    ## Example
    ```xml
    <link name="left_finger">
      <collision><geometry><box size="0.02 0.02 0.05"/></geometry></collision>
      <inertial><mass value="0.015"/><inertia ixx="2.3e-06" ixy="0" ixz="0" iyy="2.3e-06" iyz="0" izz="1e-06"/></inertial>
    </link>
    <link name="right_finger">
      <collision><geometry><box size="0.02 0.02 0.05"/></geometry></collision>
      <inertial><mass value="0.15"/><inertia ixx="2.3e-06" ixy="0" ixz="0" iyy="2.3e-06" iyz="0" izz="1e-06"/></inertial>
    </link>
    <joint name="fingers" type="fixed"><parent link="left_finger"/><child link="right_finger"/></joint>
    ```

    ## Use instead
    ```xml
    <link name="left_finger">
      <collision><geometry><box size="0.02 0.02 0.05"/></geometry></collision>
      <inertial><mass value="0.015"/><inertia ixx="2.3e-06" ixy="0" ixz="0" iyy="2.3e-06" iyz="0" izz="1e-06"/></inertial>
    </link>
    <link name="right_finger">
      <collision><geometry><box size="0.02 0.02 0.05"/></geometry></collision>
      <inertial><mass value="0.015"/><inertia ixx="2.3e-06" ixy="0" ixz="0" iyy="2.3e-06" iyz="0" izz="1e-06"/></inertial>
    </link>
    <joint name="fingers" type="fixed"><parent link="left_finger"/><child link="right_finger"/></joint>
    ```
    """
    tensors = [(link, tensor) for link in _declaring(loaded) if not massprops.is_negligible(tensor := model.declared_tensor(link))]
    sharing = Counter(tensor for _, tensor in tensors)  # copies share their tensor: only those links' shapes are compared
    copies = defaultdict(list)
    for link, tensor in tensors:
        if sharing[tensor] > 1 and (signature := geometry_signature(link)):
            copies[signature, tensor].append(link)
    for links in copies.values():
        light = min(links, key=lambda link: link.inertial.mass)
        heavy = max(links, key=lambda link: link.inertial.mass)
        if heavy.inertial.mass < MIRROR_RATIO * light.inertial.mass:
            continue
        ratio = heavy.inertial.mass / light.inertial.mass
        yield loaded.diagnostic(
            "I012",
            f"links '{light.name}' ({format_number(light.inertial.mass)} kg) and '{heavy.name}' ({format_number(heavy.inertial.mass)} kg) "
            f"have the same shapes and inertia tensor, but masses {ratio:.0f} times apart: the tensor cannot fit both",
            light.inertial.mass_at,
            "give copies of one part one mass (a decimal point out of place?), or each part its own shapes and tensor",
            subjects=(light.name, heavy.name),
        ).with_fix(_NO_MASS_FIX)


# a tensor from the geometry would fit the mass as written, right or wrong: only the part knows its mass
_NO_MASS_FIX = Fix("give each copy its mass", UNSAFE, reason="which mass is right only the part's CAD or datasheet knows")


@check("I009", "inertia-geometry-mismatch", WARNING, "A declared inertia tensor that the link's geometry proves wrong.", rule_set=RuleSet.LINT, options=(TOLERANCE, DENSITY), kind=Kind.MASS, remedy=Remedy.INERTIAL, fix=UNSAFE)
def geometry_mismatch(loaded, given):
    """## What it does
    Flags a declared tensor only when the link's geometry proves it wrong, in one of three ways:

    - **impossible**: a moment (about a link axis through the declared centre of mass) larger,
      by more than 30 % (CAD rounding, meshes a little smaller than the part), than any
      distribution of the link's mass inside the bounding box of all its visual and
      collision shapes allows. Along each axis a mass in [lo, hi] centred
      at c has a variance of at most (hi - c)(c - lo), and ixx = m (var y + var z); for a box
      of sides Lx, Ly, Lz centred on the centre of mass, ixx <= m((Ly/2)² + (Lz/2)²).
    - **rotated**: principal moments within ``tolerance`` (0.1) of those of a uniform body
      filling the collision shapes (else the visual shapes), but a principal axis more than
      30° from the body's (swapped axes, a mirrored or unturned tensor), the tensors differing
      by more than 2 x ``tolerance``. Only axes whose moment stands 15 % apart from the other
      two count: a nearly round body has no axis to get wrong. And, whatever the moments'
      size and the link's mass, a geometry clearly long along a link axis (its moment about
      it half the others or less: a finger, a hand 0.2 m long along y) whose declared
      tensor turns hardest about that axis (twice its smallest moment or more). When the
      shapes' own rotation explains it, I010 says so instead.
    - **placeholder**: a largest principal moment more than 100 times below the uniform
      body's (0.3 kg declared with a 2e-8 tensor), or a smallest principal moment more than
      20 times below the uniform body's (a finger whose moment about its long axis would
      need its mass within a fifth of its radius of the axis).

    The uniform body fills the collision shapes, else the visual shapes; and the visual
    shapes when the collision shapes' bounding box is under a tenth of theirs on its
    longest side: a 2 mm sphere on Baxter's 15 cm head is a stand-in, not the body (a
    uniform body filling it would be a point mass, far below what the head can reach).
    The fix and `urdfcli inertia --suggest` write that same body.

    With ``density`` (kg/m³) positive, the link is taken to be that uniform material: any
    tensor more than ``tolerance`` off the one it gives is flagged.

    Left alone: a CAD tensor within a few times of the uniform body's (real parts are not
    uniform: motors, shells, cables); a link lighter than 20 g fixed to a heavier body whose
    tensor adds less than 5 % to that body's (a sensor frame, whose dynamics nothing feels),
    whose turned axes are only `info` (the macro that turned them may serve heavier links
    too); geometry that cannot hold the mass (denser than osmium in its bounding box: a
    millimetre sphere standing in for a finger); links without measurable geometry; zero
    tensors (I004), tensors no body can have (I005, I006), the identity (I007) and tensors
    shared as placeholders (I008), which their own rules report. A light link that moves,
    or whose tensor matters to its body, is judged as any link.

    ## Why is this bad?
    A tensor that no body of that mass and size can have, turned the wrong way, or
    orders of magnitude off makes a simulated body turn too easily about one axis and too
    hard about another: it shakes, drifts or explodes, and model-based controllers
    compute the wrong torques.

    ## Example
    ```xml
    <link name="camera">
      <collision><geometry><box size="0.02 0.05 0.05"/></geometry></collision>
      <inertial>
        <mass value="0.1"/>
        <inertia ixx="2.42e-05" ixy="0" ixz="0" iyy="2.42e-05" iyz="0" izz="4.17e-05"/>
      </inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="camera">
      <collision><geometry><box size="0.02 0.05 0.05"/></geometry></collision>
      <inertial>
        <mass value="0.1"/>
        <inertia ixx="4.17e-05" ixy="0" ixz="0" iyy="2.42e-05" iyz="0" izz="2.42e-05"/>
      </inertial>
    </link>
    ```
    """
    options = given.options
    reported = _reported_elsewhere(loaded, options)
    alike = written_alike(loaded)
    judged: dict[tuple, Verdict | None] = {}  # links written alike, and alike lost in their bodies or not: one verdict
    for link in _declaring(loaded):
        if link.name in reported:
            continue  # I005, I006 or I008 says what is wrong with its tensor
        light = absorbed(loaded, link)
        key = (alike[link.name], light)
        if key in judged:
            found = judged[key]
        else:
            found = judged[key] = _verdict(loaded, link, light, options)
        if found is not None:
            severity = INFO if light else None  # turned axes of a link lost in its body: a note
            yield loaded.diagnostic("I009", f"inertia of link '{link.name}': {found.message}", link.inertial.inertia_at, found.hint, subjects=(link.name,))._replace(severity=severity)


def _verdict(loaded, link, light: bool, options) -> Verdict | None:
    """:func:`verdict`, unless I007 (the identity) or I010 (turned as its shapes are) says what is wrong with the tensor;
    ``light``: whether the link is lost in its body (:func:`absorbed`)."""
    found = _assess(loaded, link, options)
    if found is None or massprops.is_identity(found.declared) or _rotated(loaded, found, options["tolerance"]) is not None:
        return None
    misplaced = link.name in misplaced_centres(loaded, options)  # I013 says the centre is wrong: no reach about it
    return verdict(loaded, found, light, options["tolerance"], options.get("density") or None, misplaced)


def _reported_elsewhere(loaded, options) -> set[str]:
    """The links whose tensor I005, I006 (no body can have it) or I008 (a placeholder shared
    by links it does not fit) report: gathered once, not looked for in their lists link by link."""
    return _invalid(loaded).union(link.name for _, wrong, _ in placeholder_groups(loaded, options) for link in wrong)


def _invalid(loaded) -> set[str]:
    """The links whose tensor no body can have (I005, I006)."""
    invalid = invalid_tensors(loaded)
    return {link.name for code in ("I005", "I006") for link, _ in invalid[code]}


def _rotated(loaded, found, tolerance: float):
    """(the assessment, (rpy, difference once rotated)) when I010 reports the link it
    assessed: rotated as its shapes are, the tensor fits within the tolerance, or comes at
    least twice as close."""
    if not found.off(tolerance):
        return None
    rotated = model.rotated_fit(loaded, found)
    if rotated is None or (rotated[1] > tolerance and rotated[1] > found.difference / 2):
        return None
    return found, rotated


@check("I010", "inertia-frame-rotated", WARNING, "An inertia tensor not rotated with the geometry it was computed for.", rule_set=RuleSet.LINT, options=(TOLERANCE, DENSITY), kind=Kind.MASS, remedy=Remedy.INERTIAL, fix=UNSAFE)
def frame_rotated(loaded, given):
    """## What it does
    Flags a tensor that is more than ``tolerance`` (0.1) off its geometry's, but fits
    within it once rotated as the link's shapes are (their shared ``<origin rpy>``), or
    comes at least twice as close that way.

    Left alone: a tensor whose declared centre of mass lies outside those shapes. It was
    not computed for them (a uniform body has its centre inside), but measured on the
    part: a CAD tensor next to a rough collision cylinder that covers only the joint.

    ## Why is this bad?
    A wheel's cylinder is turned 90° about x to stand upright. The cylinder formula
    gives ``izz`` about the cylinder's axis, which is now the link's y axis; left
    unrotated, the simulated wheel resists spinning about the wrong axis.

    ## Example
    ```xml
    <link name="wheel">
      <collision>
        <origin rpy="1.5708 0 0"/>
        <geometry><cylinder radius="0.05" length="0.02"/></geometry>
      </collision>
      <inertial>
        <mass value="0.5"/>
        <inertia ixx="0.000329" ixy="0" ixz="0" iyy="0.000329" iyz="0" izz="0.000625"/>
      </inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="wheel">
      <collision>
        <origin rpy="1.5708 0 0"/>
        <geometry><cylinder radius="0.05" length="0.02"/></geometry>
      </collision>
      <inertial>
        <origin rpy="1.5708 0 0"/>
        <mass value="0.5"/>
        <inertia ixx="0.000329" ixy="0" ixz="0" iyy="0.000329" iyz="0" izz="0.000625"/>
      </inertial>
    </link>
    ```
    """
    alike = written_alike(loaded)
    judged: dict[tuple, tuple | None] = {}  # links written alike: one answer
    for link in _declaring(loaded):
        key = alike[link.name]
        if key not in judged:
            assessed = _assess(loaded, link, given.options)
            judged[key] = _rotated(loaded, assessed, given.options["tolerance"]) if assessed is not None else None
        match = judged[key]
        if match is None:
            continue
        found, (rpy, left) = match
        rpy = " ".join(f"{a:.6g}" for a in rpy)
        where = found.implied.source.split(" ")[0]
        yield loaded.diagnostic(
            "I010",
            f"inertia of link '{link.name}' is not rotated with its {where} geometry (rpy {rpy}): "
            f"{found.difference:.0%} off as declared, {left:.0%} once rotated",
            link.inertial.inertia_at,
            f'give the <inertial> <origin rpy="{rpy}"/>, or use the rotated values `urdfcli inertia --suggest` prints',
            subjects=(link.name,),
        )


CENTRE_SHARE = 0.25
"""A declared centre of mass outside the box of a link's shapes by more than this share of the
box's longest side, and by more than :data:`CENTRE_REACH`, is not that body's. On example-robot-data
the centres this far out are all wrong (TIAGo dual's arm_5 links, 8.6 cm out of an 18 cm box, the
sign of their centre swapped between the arms); a camera whose mass counts an undrawn mount is
2.9 cm out of a 5 cm box."""

CENTRE_REACH = 0.05  # m: what a part's undrawn pieces (a mount, a connector) can shift its centre by

STEEL = 7900.0
"""kg/m³: a mass denser than steel in the box of its shapes is not drawn by them, only a part of
it is (iCub's hip: 0.75 kg in a disc 7.6 cm wide and 1.3 cm thick, 10,000 kg/m³)."""


class Misplaced(NamedTuple):
    """A declared centre of mass no mass inside the link's shapes can have: the centre and the
    box (link frame), how far outside it the centre lies, and the root link (of the tree the
    link hangs from) in whose frame the centre lies inside the box, if it does."""

    centre: tuple[float, float, float]
    box: tuple
    distance: float
    inside_in_frame_of: str | None


@check("I013", "com-outside-geometry", WARNING, "A centre of mass far outside the shapes of its link.", rule_set=RuleSet.LINT, options=(TOLERANCE,), kind=Kind.MASS)
def com_outside_geometry(loaded, given):
    """## What it does
    Flags a declared centre of mass (``<inertial><origin xyz>``) lying outside the box that
    holds all the link's visual and collision shapes (in the link frame) by more than a
    quarter of the box's longest side and by more than 5 cm. When the centre, read as a
    point of the root link's frame, falls inside the box, the message says so: the centre
    was likely written in the robot's base frame, as a CAD assembly exports it.

    The centre of mass of a body lies inside the convex hull of its mass, so inside the
    box of the shapes that draw it. The margin lets a part's shapes draw a little less
    than its mass: a mount or a connector left undrawn, a centre rounded.

    Left alone: links without measurable geometry (frames, a mesh that cannot be read, or
    one in a wrong unit, which F003 reports); a mass denser than steel in the box of its
    shapes, which draw only a part of it (a motor drawn as a thin disc); links lighter than
    20 g fixed to a heavier body whose tensor adds nothing material to it; an inertial that
    I007 or I008 reports as a placeholder (its centre is part of the placeholder, at their
    ``tolerance``). I009 does not judge the moments of a link this rule reports against the
    most its mass can reach about that centre (a bound about an impossible centre proves
    nothing); what it finds wrong with the tensor otherwise still stands.

    ## Why is this bad?
    A centre of mass written in another frame (the robot's base frame, a mirrored side's)
    or left at the link's origin puts the link's mass where the link is not: gravity
    compensation and model-based controllers compute the wrong torques, and a simulated
    arm sags or swings. Doosan's m1013 description gives links 3 to 6 centres at z = 0.78
    to 1.40 m, their heights in the base frame, on links 0.1 to 0.6 m long. When the centre
    is right, the shapes are misplaced, and collisions are checked where the part is not.

    ## Example
    ```xml
    <link name="forearm">
      <collision><origin xyz="0 0 0.2"/><geometry><box size="0.08 0.08 0.4"/></geometry></collision>
      <inertial>
        <origin xyz="0 0 1.15"/>
        <mass value="3.8"/>
        <inertia ixx="0.05" ixy="0" ixz="0" iyy="0.05" iyz="0" izz="0.004"/>
      </inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="forearm">
      <collision><origin xyz="0 0 0.2"/><geometry><box size="0.08 0.08 0.4"/></geometry></collision>
      <inertial>
        <origin xyz="0 0 0.18"/>
        <mass value="3.8"/>
        <inertia ixx="0.05" ixy="0" ixz="0" iyy="0.05" iyz="0" izz="0.004"/>
      </inertial>
    </link>
    ```
    """
    for name, found in misplaced_centres(loaded, given.options).items():
        link = loaded.robot.links[name]
        centre = " ".join(f"{v:.4g}" for v in found.centre)
        box = " to ".join("(" + " ".join(f"{v:.3g}" for v in corner) + ")" for corner in found.box)
        message = (f"centre of mass of link '{link.name}' ({centre}) lies {found.distance:.3g} m outside the box {box} "
                   f"that holds its shapes (link frame): no mass inside them has that centre")
        if found.inside_in_frame_of is not None:
            message += f"; read in the frame of the root link '{found.inside_in_frame_of}', it lies inside"
        inertial = link.inertial
        yield loaded.diagnostic(
            "I013", message, inertial.origin_at if inertial.origin_at is not None else inertial.at,
            "is the centre written in another link's frame (the base's, as a CAD assembly exports it) or left at the link's origin? "
            "give it in this link's frame; if the centre is right, the shapes are misplaced",
            subjects=(link.name,),
        )


def misplaced_centres(loaded, options) -> dict:
    """Each link :func:`com_outside_geometry` reports (by name), with what it finds; worked out once (I009 asks)."""
    return once(loaded, _misplaced_within, options["tolerance"])


def _misplaced_within(loaded, tolerance: float) -> dict:
    options = {"tolerance": tolerance}
    placeholders = {link.name for link in identity_links(loaded, options)}
    placeholders.update(link.name for _, wrong, _ in placeholder_groups(loaded, options) for link in wrong)
    found = {}
    for link in _declaring(loaded):
        if link.name not in placeholders and (misplaced := _misplaced(loaded, link)) is not None:
            found[link.name] = misplaced
    return found


def _misplaced(loaded, link) -> Misplaced | None:
    if absorbed(loaded, link):
        return None
    box = model.extent(loaded, link)
    if box is None:
        return None
    low, high = box
    sides = [h - lo for lo, h in zip(low, high)]
    volume = sides[0] * sides[1] * sides[2]
    if volume <= 0 or link.inertial.mass / volume > STEEL:
        return None  # the shapes draw a part of the body only
    centre = link.inertial.origin.xyz
    distance = model.outside(centre, box)
    if distance <= max(CENTRE_SHARE * max(sides), CENTRE_REACH):
        return None
    pose = once(loaded, zero_poses).get(link.name)
    # the root of the tree the link hangs from: a model with two roots has no single one
    root = once(loaded, _roots_above).get(link.name)
    inside = pose is not None and root != link.name and model.outside(massprops.unplace(pose, centre), box) == 0
    return Misplaced(centre, box, distance, root if inside else None)


def _roots_above(loaded) -> dict[str, str]:
    """The root each link hangs from, found by the walk :func:`zero_poses` places it by."""
    robot = loaded.robot
    return {link: root for root in roots(robot) for _, _, link in walk(robot, root)}


@check("I011", "root-inertia", INFO, "The root link carries mass, which KDL ignores.", kind=Kind.MASS, rule_set=RuleSet.LINT)
def root_inertia(loaded, given):
    """## What it does
    Notes (info) a root link with a mass of a gram or more. Lighter roots (the usual
    workaround, a dummy root of 1e-6 kg) are left alone.

    ## Why is this bad?
    KDL (and so KDL-based dynamics such as `kdl_parser` users) cannot give the root
    link inertia: it warns and drops it, so those dynamics lose that body. Pinocchio,
    Drake and simulators use it: that is why this is only a note.

    ## Example
    ```xml
    <link name="base_link">
      <inertial><mass value="15"/><inertia ixx="0.28" ixy="0" ixz="0" iyy="0.28" iyz="0" izz="0.53"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="base_footprint"/>
    <joint name="base_footprint_joint" type="fixed">
      <parent link="base_footprint"/>
      <child link="base_link"/>
    </joint>
    <link name="base_link">
      <inertial><mass value="15"/><inertia ixx="0.28" ixy="0" ixz="0" iyy="0.28" iyz="0" izz="0.53"/></inertial>
    </link>
    ```
    """
    root = loaded.root
    link = loaded.robot.links.get(root) if root is not None else None
    if link is not None and link.inertial is not None and (link.inertial.mass or 0) >= ROOT_MASS:
        yield loaded.diagnostic(
            "I011",
            f"root link '{root}' has mass {format_number(link.inertial.mass)}, which KDL ignores",
            link.inertial.at,
            f"add a massless root link and a fixed joint from it to '{root}'",
            subjects=(root,),
        )


# -- what the geometry proves --------------------------------------------------------
PLACEHOLDER_FACTOR = 100.0
"""A tensor this many times below a uniform body of the same mass and geometry is a placeholder."""

AXIS_FACTOR = 20.0
"""A smallest principal moment this many times below the uniform body's (the mass would have to
sit within a fifth of the shape's radius of that axis): Kinova's finger links, 23 to 33 times
below about their long axis."""

AXES = ("ixx", "iyy", "izz")
UNITS_FACTOR = 100.0  # a tensor this far off suggests units (g for kg, mm for m), not a rounding
TURNED = 30.0  # degrees between principal axes that say the axes are swapped or rotated


class Verdict(NamedTuple):
    """What the geometry proves wrong about a declared tensor: ``kind`` is ``impossible``,
    ``rotated`` or ``placeholder``; ``factor`` says by how much."""

    kind: str
    factor: float
    message: str
    hint: str


LONG = 0.5  # a geometry whose smallest moment is at most half the next is long along that axis
HARDEST = 2.0  # a declared moment about that axis this many times the declared smallest is its largest: swapped


def _long_axis_swapped(declared, expected) -> tuple[str, float, float] | None:
    """(axis, declared moment about it, how many times the smallest) when the geometry is
    clearly long along a link axis (its moment about it half the others or less)
    and the declared tensor turns hardest about that axis: a finger or a hand whose axes
    were swapped, told whatever its mass and however its moments compare in size."""
    moments = [expected[i][i] for i in range(3)]
    axis = min(range(3), key=lambda i: moments[i])
    others = [moments[i] for i in range(3) if i != axis]
    if moments[axis] <= 0 or any(abs(expected[i][j]) > 1e-3 * max(moments) for i in range(3) for j in range(3) if i != j):
        return None  # a geometry turned off the link's axes: the rotation rules judge it
    if moments[axis] > LONG * min(others):
        return None  # not clearly long along one axis
    declared_moments = massprops.principal_moments(declared)
    about = declared[axis][axis]
    if declared_moments[0] <= 0 or about < max(declared[i][i] for i in range(3)) or about < HARDEST * declared_moments[0]:
        return None
    return "xyz"[axis], about, about / declared_moments[0]


def verdict(
    loaded: Loaded, found: Assessment, light: bool, tolerance: float = massprops.TOLERANCE, density: float | None = None, misplaced: bool = False,
) -> Verdict | None:
    """The one thing the geometry proves wrong about a link's tensor, if any: ``found`` is its
    assessment (at ``density``), ``light`` whether it is lost in its body (:func:`absorbed`),
    ``misplaced`` whether its centre of mass is far outside its shapes (I013), about which
    no reach is judged.

    In order: a moment larger than any distribution of the mass in the geometry's bounding
    box allows; principal moments that match the geometry's on axes that do not; with a
    density, any difference beyond the tolerance from that uniform body; a tensor orders of
    magnitude below a uniform body's. Anything else (a CAD tensor within a few times of the
    uniform body's) is left alone."""
    link = found.link
    declared = declared_body(link)
    if declared is None or massprops.is_negligible(declared.tensor):
        return None
    # a light link, lost in its body: only a rotation, which a formula got wrong, is worth saying
    limits = reach(loaded, link, declared) if not light and not misplaced else None
    if limits is not None:
        worst = max(range(3), key=lambda i: declared.tensor[i][i] / limits.bounds[i] if limits.bounds[i] > 0 else math.inf)
        moment, most = declared.tensor[worst][worst], limits.bounds[worst]
        if moment > OVERREACH * most:
            factor = moment / most if most > 0 else math.inf
            sides = " x ".join(f"{side:.3g}" for side in limits.sides)
            times = f"{factor:.1f} times" if factor < math.inf else "infinitely more than"
            return Verdict(
                "impossible", factor,
                f"{AXES[worst]}={moment:.3g} (link axes) is {times} the most {number(declared.mass)} kg can reach "
                f"about the declared centre of mass inside the {sides} m box its shapes fill: {most:.3g}",
                f"the tensor, the centre of mass or the mass is wrong{' (units?)' if factor >= UNITS_FACTOR else ''}; "
                "`urdfcli inertia --suggest` prints a uniform body's values as a start",
            )
    if found.expected is None or massprops.is_zero(found.expected):
        return None
    source = found.implied.source
    apart = found.difference > 2 * tolerance  # else no axes are wrong: most tensors, not compared further
    turned = axes_apart(found.declared, found.expected) if apart and massprops.moments_difference(found.declared, found.expected) <= tolerance else 0.0
    if turned > TURNED:
        negated = massprops.negated_products(found.declared)
        if massprops.relative_difference(negated, found.expected) <= tolerance:  # the sign of its products only
            return Verdict(
                "rotated", turned,
                f"its products of inertia have the signs opposite to those its {source} gives: declared {tensor_text(found.declared, found.expected)}, "
                f"the {source} gives {tensor_text(found.expected, found.declared)}; the other sign convention for them (∫xy dm for -∫xy dm), which some CAD tools export",
                f"negate the products of inertia: {massprops.inertia_element(negated)}",
            )
        return Verdict(
            "rotated", turned,
            f"its principal moments match its {source}, but on axes {turned:.0f}° away: declared {tensor_text(found.declared, found.expected)}, "
            f"the {source} gives {tensor_text(found.expected, found.declared)}",
            "the axes are swapped or rotated: `urdfcli inertia --suggest` prints the tensor on the geometry's axes",
        )
    swapped = _long_axis_swapped(found.declared, found.expected) if apart else None
    if swapped is not None:
        axis, about, largest = swapped
        return Verdict(
            "rotated", 90.0,
            f"its {source} {'are' if 'shapes' in source else 'is'} long along {axis}, so its moment about {axis} is its smallest, but the declared tensor turns "
            f"hardest about {axis}: {about:.3g}, {largest:.3g} times its smallest; declared {tensor_text(found.declared, found.expected)}, "
            f"the {source} gives {tensor_text(found.expected, found.declared)}",
            "the axes are swapped: `urdfcli inertia --suggest` prints the tensor on the geometry's axes",
        )
    if density is not None and found.off(tolerance):  # the link is said to be that uniform material
        times = found.times()
        off = f"{times} than" if times is not None else f"{found.difference:.0%} off"
        return Verdict(
            "density", found.difference,
            f"it is {off} what its {source} implies at density {number(density)}: "
            f"declared {tensor_text(found.declared, found.expected)}, expected {tensor_text(found.expected, found.declared)}",
            "`urdfcli inertia --suggest --density ...` prints the uniform body's <inertial>",
        )
    if light:
        return None
    moments, expected_moments = massprops.principal_moments(found.declared), massprops.principal_moments(found.expected)
    if moments[2] * PLACEHOLDER_FACTOR < expected_moments[2]:
        factor = expected_moments[2] / moments[2]
        return Verdict(
            "placeholder", factor,
            f"its largest moment {moments[2]:.3g} is {factor:.0f} times below the {expected_moments[2]:.3g} of a uniform body of "
            f"{number(declared.mass)} kg filling its {source}: a placeholder",
            "`urdfcli inertia --suggest` prints the uniform body's tensor, a better start than the placeholder",
        )
    smallest, expected_smallest = moments[0], expected_moments[0]
    if expected_smallest > 0 and smallest * AXIS_FACTOR < expected_smallest:
        what = "is 0, where" if smallest <= 0 else f"{smallest:.3g} is {expected_smallest / smallest:.0f} times below"
        return Verdict(
            "placeholder", expected_smallest / smallest if smallest > 0 else math.inf,
            f"its smallest principal moment {what} a uniform body of {number(declared.mass)} kg filling its {source} has "
            f"{expected_smallest:.3g}: no body of that shape turns so easily about that axis",
            "`urdfcli inertia --suggest` prints the uniform body's tensor, a better start",
        )
    return None
