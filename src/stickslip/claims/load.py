"""Claim rows read from the claims files and checked: each row against its typed model, then what a row
alone cannot show (pinned ids, disc-speed twins, every dataset a claim reads written by some rule)."""

from __future__ import annotations

from pathlib import Path

from .rows import Claim, ClaimRow


class ClaimsError(ValueError):
    """A claims file is malformed; the message names the file, the claim and the key."""


def load_claims(paths) -> list[Claim]:
    """Every row of the claims files, each checked against ``ClaimRow`` (stickslip.claims.rows); an error
    names the file, the row's id and the key. Rows come back typed (``Claim``: the checked row and the file
    it came from)."""
    from pydantic import ValidationError

    from stickslip.io.typed_errors import typed_errors
    from stickslip.io.yaml_files import YamlFileError, load_yaml

    claims, seen = [], {}
    for path in sorted(Path(p) for p in paths):
        try:
            rows = load_yaml(path) or []
        except YamlFileError as exc:
            raise ClaimsError(str(exc)) from None
        if not isinstance(rows, list):
            raise ClaimsError(f"{path}: expected a list of claim rows")
        for i, row in enumerate(rows):
            where = f"{path}: row {i} ({row.get('id', '?') if isinstance(row, dict) else '?'})"
            if not isinstance(row, dict):
                raise ClaimsError(f"{where}: expected a mapping")
            try:
                checked = ClaimRow.model_validate(row)
            except ValidationError as exc:
                errors = typed_errors(exc).replace("\n", "; ")  # the config's format: ``key: message``
                raise ClaimsError(f"{where}: {errors}") from None
            if checked.id in seen:
                raise ClaimsError(f"{where}: id {checked.id!r} already used in {seen[checked.id]}")
            seen[checked.id] = path
            # checked above as a ClaimRow, where ``file`` is an unknown key: add it without a second check
            claims.append(Claim.model_construct(**dict(checked), file=str(path)))
    return claims


def check_claims(
    claims: list[Claim],
    readings,
    known_readings=None,
    pinned_ids=None,
    producible=None,
    variables_of=None,
    catalogue=None,
) -> None:
    """What a row alone cannot show: per-reading entries name known readings; the set of claim ids is the
    pinned one (a deleted row or file is an error listing the ids it lost); every dataset a claim reads,
    per claims reading (``readings``), is a catalogue path (``catalogue``: path -> Entry of
    stickslip.catalogue), is an output of some rule (``producible(path) -> bool``), and names a variable
    that dataset holds where ``variables_of(path)`` knows them (None: not known)."""
    known = set(known_readings or ())
    for c in claims if known_readings is not None else []:
        where = f"{c.file}: claim {c.id}"
        for key in ("expected", "note", "invariance"):
            if isinstance(getattr(c, key), dict):
                for name in getattr(c, key):
                    if name != "default" and name not in known:
                        raise ClaimsError(f"{where}: {key}.{name}: not a reading ({sorted(known)})")
    _check_speed_twins(claims)
    if pinned_ids is not None:
        ids = {c.id for c in claims}
        lost, new = sorted(set(pinned_ids) - ids), sorted(ids - set(pinned_ids))
        if lost:
            raise ClaimsError(f"claims pinned but not found in any claims file: {', '.join(lost)}")
        if new:
            raise ClaimsError(
                f"claims not in the pinned id list (add them to it deliberately): {', '.join(new)}"
            )
    for c, key, ref, path in claimed_paths(claims, readings):
        where = f"{c.file}: claim {c.id}: {key}"
        if catalogue is not None and path not in catalogue:
            raise ClaimsError(f"{where}: no rule writes {path!r}: not a catalogue path (stickslip.catalogue)")
        if producible is not None and not producible(path):
            raise ClaimsError(f"{where}: no rule writes {path!r}")
        known_vars = variables_of(path) if variables_of is not None else None
        if known_vars is not None and ref.variable not in known_vars:
            var_key = key.replace("dataset", "variable")
            raise ClaimsError(
                f"{c.file}: claim {c.id}: {var_key}: {ref.variable!r} is not a variable that {path!r} holds"
            )


def claimed_paths(claims: list[Claim], readings):
    """(claim, key, row or operand, dataset path) of every dataset every claim reads, per claims reading for
    a path with the ``{reading}`` placeholder."""
    for c in claims:
        for key, ref in c.dataset_refs():
            for r in readings_of(c, readings) if "{reading}" in ref.dataset else [""]:
                yield c, key, ref, ref.dataset.format(reading=r)


#: The two disc speeds of the beam-on-disc scenes, as their dataset names spell them, and in words.
DISC_SPEEDS = {"15p2rpm": "15.2 rev/min (stated)", "0p5mm_s": "0.5 mm/s (implied)"}


def disc_speed(claim: Claim) -> str:
    """The disc speed a claim reads (one of DISC_SPEEDS), named by its datasets or, in a study over several
    speeds, by the variables it reads; ``""`` for none or several."""
    names = [ref.dataset for _, ref in claim.dataset_refs()]
    names += [ref.variable or "" for _, ref in claim.dataset_refs()]
    found = {s for name in names for s in DISC_SPEEDS if f"_{s}" in name}
    return found.pop() if len(found) == 1 else ""


def _check_speed_twins(claims: list[Claim]) -> None:
    """Every beam-on-disc evidence row names the disc speed it reads, and a claim read at one disc speed is
    decided at the other too (``twin``: the row that does, reading the other speed, and naming this row
    back); either exception says why (``one_speed``)."""
    by_id = {c.id: c for c in claims}
    for c in claims:
        where = f"{c.file}: claim {c.id}"
        speed = disc_speed(c)
        if c.model is not None and c.evidence == "evidence" and not speed and not c.one_speed:
            raise ClaimsError(
                f"{where}: a beam-on-disc row names no disc speed: read a dataset or variable named by its "
                "speed (_15p2rpm, _0p5mm_s) or say why the speed does not matter (one_speed: <reason>)"
            )
        if c.twin is None:
            if speed and not c.one_speed:
                raise ClaimsError(
                    f"{where}: reads the {speed} scenes only: add its twin at the other speed (twin: <id>) "
                    "or say why not (one_speed: <reason>)"
                )
            continue
        twin = by_id.get(c.twin)
        if twin is None:
            raise ClaimsError(f"{where}: twin: {c.twin!r} is not a claim id")
        if twin.twin != c.id:
            raise ClaimsError(f"{where}: twin: {c.twin!r} does not name {c.id!r} back")
        if not speed or disc_speed(twin) in ("", speed):
            raise ClaimsError(f"{where}: twin: {c.twin!r} does not read the other disc speed")


def readings_of(claim: Claim, readings: list[str]) -> list[str]:
    return list(readings) if any("{reading}" in p for p in claim.dataset_paths()) else [""]


def required_datasets(claims: list[Claim], readings: list[str]) -> list[str]:
    return sorted({path for *_, path in claimed_paths(claims, readings)})
