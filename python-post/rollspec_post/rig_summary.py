"""The rig's main parameters from the resolved study text a result stores (provenance attribute
`study`): what a reader of the report needs to know what was simulated without reading the INI."""
import configparser

# section, keys shown (in this order); a key absent from the study is left out, a section with none too
RIG_KEYS = (("beam", ("support", "length", "width", "thickness", "youngs_modulus", "density", "loss_factor")),
            ("ball", ("radius", "density", "youngs_modulus", "speed", "start", "end")),
            ("contact", ("law", "blocked_force", "k0", "damping", "loss", "filter")),
            ("roughness", ("spacing", "band_limit")),
            ("texture", ("source", "rms_kind", "rms", "hurst", "profiles")),
            ("sensors", ("positions", "average")))
UNITS = {"length": "m", "width": "m", "thickness": "m", "youngs_modulus": "Pa", "density": "kg/m³", "radius": "m",
         "speed": "m/s", "start": "m", "end": "m", "k0": "N/m", "damping": "N s/m", "rms": "m", "positions": "m",
         "spacing": "m"}


def parse_study(text):
    """The study as {section: {key: value}}; {} when it is not INI text (an old or damaged file)."""
    parser = configparser.ConfigParser(interpolation=None, strict=False, inline_comment_prefixes=("#", ";"))
    try:
        parser.read_string(text or "")
    except configparser.Error:
        return {}
    return {s: dict(parser[s]) for s in parser.sections()}


def study_scene(text):
    """The scene a study's text names (the value of its first `scene` key, read line by line as the scripts
    and tests that run every study read it), or None."""
    for line in text.splitlines():
        key, _, value = line.partition("=")
        if key.strip() == "scene":
            return value.strip()
    return None


def shown_value(key, value):
    if key == "profiles":  # fifteen file names say less than their count
        files = [v for v in value.split(",") if v.strip()]
        return f"{len(files)} measured profile{'s' if len(files) != 1 else ''}" if files else "none"
    unit = UNITS.get(key)
    return f"{value} {unit}" if unit and value not in ("0", "") else value


def contact_keys(values):
    """The [contact] keys the study's own law uses (a resolved study holds every key, k0 of a Hertz law too):
    k0 and blocked_force are the linearised law's (k0 from a solver's table when blocked_force = solver);
    loss is the nonlinear laws'; the filter acts on the line texture, which law = path and a solver's blocked
    force do not use."""
    law, force = values.get("law", "hertz"), values.get("blocked_force", "spring")
    keys = {"law", "damping"}
    if law == "linearised":
        keys |= {"blocked_force"} | ({"k0", "filter"} if force == "spring" else set())
    else:
        keys |= {"loss"} | ({"filter"} if law != "path" else set())
    return keys


def rig_parameters(text):
    """[(section, [(key, value shown)])] of the sections of RIG_KEYS the study holds ([contact]: the keys of its
    law only)."""
    study = parse_study(text)
    out = []
    for section, keys in RIG_KEYS:
        values = study.get(section, {})
        used = contact_keys(values) if section == "contact" else set(keys)
        rows = [(k, shown_value(k, values[k])) for k in keys if k in values and k in used]
        if rows:
            out.append((section, rows))
    return out
