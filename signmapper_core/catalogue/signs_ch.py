"""Swiss sign definitions (SSV, SR 741.21): ids, names de/fr/it, colour, shape, formats, drawing.

Ids are SSV numbers; signs carrying a value get ``-<value>`` (``2.30-50``).
The colour class is the dominant colour the detector segments on. The drawings
are the project's own stylised ones (the catalogue masters come from the official
artwork where it exists, see ``official_ch``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from . import formats as F
from . import frames, shapes
from . import pictograms as pg
from .drawing import Drawing
from .pen import Pen
from .style import FaceStyle
from .text_panels import TEXT_PANELS


@dataclass(frozen=True)
class SignDef:
    id: str
    names: dict
    colour: str
    shape: str
    formats: dict
    size_certain: bool
    draw: Callable[[FaceStyle], Drawing]


SIGNS: dict[str, SignDef] = {}


def _add(id_, de, fr, it, colour, shape, fmts, certain, draw):
    if id_ in SIGNS:
        raise ValueError(f"duplicate sign id {id_}")
    SIGNS[id_] = SignDef(id_, {"de": de, "fr": fr, "it": it}, colour, shape, dict(fmts), certain, draw)


def _mirror(fn, *args, **kw):
    return lambda p: fn(p.sub(0, 0, 1, mirror=True, jitter=False), *args, **kw)


def _at(fn, dx=0.0, dy=0.0, s=1.0, mirror=False, *args, **kw):
    return lambda p: fn(p.sub(dx, dy, s, mirror=mirror), *args, **kw)


def _all(*fns):
    def content(p: Pen):
        for fn in fns:
            fn(p)
    return content


def _text(text, dy=0.0, h=1.0, c="black", mw=2.1):
    return lambda p: p.text(text, 0, dy, h, c, max_width=mw)


# --------------------------------------------------------------------------- families
def danger(id_, de, fr, it, content):
    _add(id_, de, fr, it, "red", "triangle", F.TRIANGLE, True, lambda st: frames.triangle(st, content))


def prohibition(id_, de, fr, it, content, bar=False):
    full = _all(content, pg.bar) if bar else content
    _add(id_, de, fr, it, "red", "circle", F.ROUND, True, lambda st: frames.disc(st, full))


def mandatory(id_, de, fr, it, content):
    _add(id_, de, fr, it, "blue", "circle", F.ROUND, True,
         lambda st: frames.disc(st, content, fill="blue", rim_colour=None, edge="white"))


def info(id_, de, fr, it, content, colour="blue"):
    _add(id_, de, fr, it, colour, "square", F.SQUARE, False, lambda st: frames.panel(st, content))


def end_sign(id_, de, fr, it, content):
    def draw(st):
        d = frames.disc(st, content, fill="white", rim_colour=None, edge="grey")
        frames.diagonal_stripes(d, shapes.regular_polygon(32, 0.5, 0.5, 0.47), "black", n=5, spacing=0.05,
                                width=0.016 * st.stroke_scale)
        return d
    _add(id_, de, fr, it, "white", "circle", F.ROUND, True, draw)


# --------------------------------------------------------------------------- 1 danger signs
danger("1.01", "Rechtskurve", "Virage à droite", "Curva a destra", pg.road_curve)
danger("1.02", "Linkskurve", "Virage à gauche", "Curva a sinistra", _mirror(pg.road_curve))
danger("1.03", "Doppelkurve nach rechts beginnend", "Double virage, le premier à droite",
       "Doppia curva, la prima a destra", pg.road_double_curve)
danger("1.04", "Doppelkurve nach links beginnend", "Double virage, le premier à gauche",
       "Doppia curva, la prima a sinistra", _mirror(pg.road_double_curve))
danger("1.05", "Schleudergefahr", "Chaussée glissante", "Strada sdrucciolevole",
       _all(_at(pg.car_rear, 0, -0.45, 0.55), _at(pg.skid_marks, 0, 0, 1.0)))
danger("1.06", "Unebene Fahrbahn", "Cassis", "Cunetta", pg.bumps)
danger("1.07", "Engpass", "Chaussée rétrécie", "Restringimento", pg.narrowing)
danger("1.08", "Verengung rechts", "Chaussée rétrécie à droite", "Restringimento a destra",
       lambda p: pg.narrowing(p, left=False))
danger("1.09", "Verengung links", "Chaussée rétrécie à gauche", "Restringimento a sinistra",
       lambda p: pg.narrowing(p, right=False))
danger("1.10", "Gefährliches Gefälle", "Descente dangereuse", "Discesa pericolosa", pg.gradient)
danger("1.11", "Starke Steigung", "Forte montée", "Salita ripida",
       lambda p: (p.sub(0, 0, 1, mirror=True, jitter=False).poly([(-0.95, -0.25), (0.95, 0.75), (-0.95, 0.75)],
                                                                "black"),
                  p.text("10%", 0.38, 0.42, 0.34, "white", max_width=0.9)))
danger("1.12", "Rollsplitt", "Gravillon", "Ghiaia", pg.gravel)
danger("1.13", "Steinschlag", "Chute de pierres", "Caduta massi", pg.rockfall)
danger("1.14", "Baustelle", "Travaux", "Lavori", pg.worker)
danger("1.15", "Schranken", "Barrières", "Barriere", pg.barrier)
danger("1.16", "Bahnübergang ohne Schranken", "Passage à niveau sans barrières",
       "Passaggio a livello senza barriere", pg.locomotive)
danger("1.18", "Strassenbahn", "Tramway ou chemin de fer routier", "Tram", pg.tram)
danger("1.22", "Fussgängerstreifen", "Passage pour piétons", "Passaggio pedonale",
       _all(_at(pg.pedestrian, 0, -0.2, 0.78), pg.zebra))
danger("1.23", "Kinder", "Enfants", "Bambini", pg.children)
danger("1.24", "Wildwechsel", "Passage de gibier", "Passaggio di selvaggina", pg.deer)
danger("1.25", "Tiere", "Animaux", "Animali", pg.cow)
danger("1.26", "Gegenverkehr", "Circulation en sens inverse", "Traffico in senso inverso", pg.two_way)
danger("1.27", "Lichtsignale", "Signaux lumineux", "Segnali luminosi", pg.traffic_lights)
danger("1.30", "Andere Gefahren", "Autres dangers", "Altri pericoli", pg.exclamation)
danger("1.31", "Stau", "Bouchon", "Colonna", pg.queue)
danger("1.32", "Radfahrer", "Cyclistes", "Ciclisti", pg.cyclist)

# --------------------------------------------------------------------------- 2 prohibitions
prohibition("2.01", "Allgemeines Fahrverbot in beiden Richtungen",
            "Interdiction générale de circuler dans les deux sens",
            "Divieto generale di circolare nelle due direzioni", None)
_add("2.02", "Einfahrt verboten", "Accès interdit", "Divieto di accesso", "red", "circle", F.ROUND, True,
     lambda st: frames.disc(st, lambda p: p.rect(-1.05, -0.22, 1.05, 0.22, "white"), fill="red"))
prohibition("2.03", "Verbot für Motorwagen", "Circulation interdite aux voitures automobiles",
            "Divieto di circolazione per autoveicoli", pg.car_side)
prohibition("2.04", "Verbot für Motorräder", "Circulation interdite aux motocycles",
            "Divieto di circolazione per motoveicoli", pg.motorcycle)
prohibition("2.05", "Verbot für Fahrräder und Motorfahrräder", "Circulation interdite aux cycles et aux cyclomoteurs",
            "Divieto di circolazione per velocipedi e ciclomotori", pg.bicycle)
prohibition("2.06", "Verbot für Motorfahrräder", "Circulation interdite aux cyclomoteurs",
            "Divieto di circolazione per ciclomotori", pg.moped)
prohibition("2.07", "Verbot für Lastwagen", "Circulation interdite aux camions",
            "Divieto di circolazione per autocarri", pg.lorry_side)
prohibition("2.08", "Verbot für Gesellschaftswagen", "Circulation interdite aux autocars",
            "Divieto di circolazione per autobus", pg.bus_side)
prohibition("2.09", "Verbot für Anhänger", "Circulation interdite aux remorques",
            "Divieto di circolazione per rimorchi", pg.trailer)
prohibition("2.10.1", "Verbot für Fahrzeuge mit gefährlicher Ladung",
            "Circulation interdite aux véhicules transportant des marchandises dangereuses",
            "Divieto di circolazione per veicoli che trasportano merci pericolose",
            _all(pg.lorry_side, lambda p: p.rect(-0.45, -0.45, -0.05, -0.15, "orange", 0.02)))
prohibition("2.11", "Verbot für Fahrzeuge mit wassergefährdender Ladung",
            "Circulation interdite aux véhicules dont le chargement peut altérer les eaux",
            "Divieto di circolazione per veicoli il cui carico può inquinare le acque",
            _all(_at(pg.lorry_side, 0, -0.2, 0.85),
                 *[(lambda x: (lambda p: p.ellipse(x, 0.72, 0.08, 0.13, "black")))(x) for x in (-0.5, 0, 0.5)]))
prohibition("2.12", "Verbot für Tiere", "Circulation interdite aux animaux", "Divieto di circolazione per animali",
            lambda p: pg.horse_rider(p, "black"))
prohibition("2.13", "Verbot für Motorwagen und Motorräder",
            "Circulation interdite aux voitures automobiles et aux motocycles",
            "Divieto di circolazione per autoveicoli e motoveicoli",
            _all(_at(pg.car_side, 0, -0.45, 0.6), _at(pg.motorcycle, 0, 0.5, 0.55)))
prohibition("2.14", "Verbot für Motorwagen, Motorräder und Motorfahrräder",
            "Circulation interdite aux voitures automobiles, aux motocycles et aux cyclomoteurs",
            "Divieto di circolazione per autoveicoli, motoveicoli e ciclomotori",
            _all(_at(pg.car_side, 0, -0.65, 0.5), _at(pg.motorcycle, 0, 0.05, 0.45), _at(pg.moped, 0, 0.7, 0.42)))
prohibition("2.15", "Verbot für Fussgänger", "Accès interdit aux piétons", "Divieto di transito per i pedoni",
            pg.pedestrian)
prohibition("2.16-3.5", "Höchstgewicht", "Poids maximal", "Peso massimo", _text("3.5t", 0, 0.75))
prohibition("2.17-10", "Achsdruck", "Charge par essieu", "Carico per asse",
            _all(_text("10t", -0.15, 0.7), lambda p: p.line([(-0.6, 0.55), (0.6, 0.55)], 0.1, "black"),
                 lambda p: p.circle(-0.6, 0.7, 0.16, "black"), lambda p: p.circle(0.6, 0.7, 0.16, "black")))
prohibition("2.18-2.3", "Höchstbreite", "Largeur maximale", "Larghezza massima",
            _all(_text("2.3m", 0, 0.6, mw=1.3), pg.width_marks))
prohibition("2.19-3.8", "Höchsthöhe", "Hauteur maximale", "Altezza massima",
            _all(_text("3.8m", 0, 0.6, mw=1.6), pg.height_marks))
prohibition("2.20-10", "Höchstlänge", "Longueur maximale", "Lunghezza massima",
            _all(_at(pg.lorry_side, 0, -0.35, 0.6), _text("10m", 0.45, 0.55),
                 lambda p: p.line([(-0.9, 0.05), (0.9, 0.05)], 0.06, "black")))
for _v in (20, 30, 40, 50, 60, 70, 80, 100, 120):
    prohibition(f"2.30-{_v}", f"Höchstgeschwindigkeit {_v}", f"Vitesse maximale {_v}", f"Velocità massima {_v}",
                _text(str(_v), 0, 1.3, mw=2.1))


def _general_limit(end: bool):
    """2.30.1 / 2.53.1: a 50 disc with GENERELL written in the (red or grey) rim; the end sign is striped."""
    ring, ink = ("grey", "grey") if end else ("red", "black")

    def content(p: Pen):
        p.text("50", 0, 0.05, 1.2, ink, max_width=1.8)
        p.text("GENERELL", 0, -1.45, 0.22, "white", max_width=1.05)

    def draw(st):
        d = frames.disc(st, content, rim_colour=ring, rim=0.17)
        if end:
            frames.diagonal_stripes(d, shapes.regular_polygon(32, 0.5, 0.5, 0.33), "black", n=5, spacing=0.05,
                                    width=0.016 * st.stroke_scale)
        return d
    return draw


_add("2.30.1", "Höchstgeschwindigkeit 50 generell", "Vitesse maximale 50, limite générale",
     "Velocità massima 50, limite generale", "red", "circle", F.ROUND, True, _general_limit(False))
mandatory("2.31-60", "Mindestgeschwindigkeit", "Vitesse minimale", "Velocità minima", _text("60", 0, 1.2, "white"))
mandatory("2.32", "Vorgeschriebene Fahrtrichtung rechts", "Sens obligatoire à droite",
          "Direzione obbligatoria a destra", lambda p: p.arrow([(-0.9, 0), (0.95, 0)], 0.32, "white", 0.55, 0.5))
mandatory("2.33", "Vorgeschriebene Fahrtrichtung links", "Sens obligatoire à gauche",
          "Direzione obbligatoria a sinistra", lambda p: p.arrow([(0.9, 0), (-0.95, 0)], 0.32, "white", 0.55, 0.5))
mandatory("2.34", "Hindernis rechts umfahren", "Obstacle à contourner par la droite", "Ostacolo da scansare a destra",
          lambda p: p.arrow([(-0.62, -0.62), (0.68, 0.68)], 0.32, "white", 0.55, 0.5))
mandatory("2.35", "Hindernis links umfahren", "Obstacle à contourner par la gauche", "Ostacolo da scansare a sinistra",
          lambda p: p.arrow([(0.62, -0.62), (-0.68, 0.68)], 0.32, "white", 0.55, 0.5))
mandatory("2.36", "Geradeausfahren", "Circuler tout droit", "Diritto",
          lambda p: p.arrow([(0, 0.95), (0, -0.95)], 0.32, "white", 0.55, 0.5))
mandatory("2.37", "Rechtsabbiegen", "Obliquer à droite", "Svoltare a destra",
          lambda p: pg.turn_arrow(p, "white"))
mandatory("2.38", "Linksabbiegen", "Obliquer à gauche", "Svoltare a sinistra",
          _mirror(pg.turn_arrow, "white"))
mandatory("2.39", "Rechts- oder Linksabbiegen", "Obliquer à droite ou à gauche", "Svoltare a destra o a sinistra",
          _all(lambda p: pg.turn_arrow(p.sub(0.12, 0, 1, jitter=False), "white", 0.26),
               lambda p: pg.turn_arrow(p.sub(-0.12, 0, 1, mirror=True, jitter=False), "white", 0.26)))
mandatory("2.40", "Geradeaus oder Rechtsabbiegen", "Circuler tout droit ou obliquer à droite", "Diritto o a destra",
          _all(lambda p: p.arrow([(-0.1, 0.95), (-0.1, -0.95)], 0.26, "white", 0.45, 0.4),
               lambda p: pg.turn_arrow(p.sub(0, 0.25, 0.85, jitter=False), "white", 0.3)))
mandatory("2.41", "Geradeaus oder Linksabbiegen", "Circuler tout droit ou obliquer à gauche", "Diritto o a sinistra",
          _all(lambda p: p.arrow([(0.1, 0.95), (0.1, -0.95)], 0.26, "white", 0.45, 0.4),
               lambda p: pg.turn_arrow(p.sub(0, 0.25, 0.85, mirror=True, jitter=False), "white", 0.3)))
mandatory("2.41.1", "Kreisverkehrsplatz", "Carrefour à sens giratoire", "Area con percorso rotatorio obbligatorio",
          pg.roundabout)
prohibition("2.42", "Abbiegen nach rechts verboten", "Interdiction d'obliquer à droite", "Divieto di svoltare a destra",
            lambda p: pg.turn_arrow(p.sub(-0.05, 0, 0.9), "black", 0.26), bar=True)
prohibition("2.43", "Abbiegen nach links verboten", "Interdiction d'obliquer à gauche",
            "Divieto di svoltare a sinistra",
            lambda p: pg.turn_arrow(p.sub(0.05, 0, 0.9, mirror=True), "black", 0.26), bar=True)
prohibition("2.44", "Überholen verboten", "Interdiction de dépasser", "Divieto di sorpasso",
            _all(_at(pg.car_rear, -0.5, 0.05, 0.5, False, "red"), _at(pg.car_rear, 0.5, 0.05, 0.5)))
prohibition("2.45", "Überholen für Lastwagen verboten", "Interdiction aux camions de dépasser",
            "Divieto di sorpasso per autocarri",
            _all(_at(pg.lorry_rear, -0.5, 0.05, 0.55, False, "red"), _at(pg.car_rear, 0.5, 0.05, 0.5)))
prohibition("2.46", "Wenden verboten", "Interdiction de faire demi-tour", "Divieto d'inversione di marcia",
            pg.u_turn, bar=True)
prohibition("2.47-70", "Mindestabstand", "Distance minimale", "Distanza minima",
            _all(_at(pg.car_side, -0.52, -0.45, 0.42), _at(pg.car_side, 0.52, -0.45, 0.42),
                 _text("70m", 0.35, 0.6, mw=1.5)))
mandatory("2.48", "Schneeketten obligatorisch", "Chaînes à neige obligatoires", "Catene da neve obbligatorie",
          pg.tyre_with_chains)


def _stopping(cross: bool):
    """Blue disc with the red rim and bar(s) of the SSV (rim 1/6, bars 1/12 of the diameter): red dominates."""

    def content(p: Pen):
        p.line([(-1.3, -1.3), (1.3, 1.3)], 0.28, "red", scaled=False)
        if cross:
            p.line([(-1.3, 1.3), (1.3, -1.3)], 0.28, "red", scaled=False)
    return lambda st: frames.disc(st, content, fill="blue", rim=0.167)


_add("2.49", "Halten verboten", "Interdiction de s'arrêter", "Divieto di fermata", "red", "circle", F.ROUND, True,
     _stopping(True))
_add("2.50", "Parkieren verboten", "Interdiction de parquer", "Divieto di parcheggio", "red", "circle", F.ROUND,
     True, _stopping(False))
end_sign("2.53-50", "Ende der Höchstgeschwindigkeit", "Fin de la vitesse maximale", "Fine della velocità massima",
         _text("50", 0, 1.3, "grey"))
end_sign("2.53-60", "Ende der Höchstgeschwindigkeit", "Fin de la vitesse maximale", "Fine della velocità massima",
         _text("60", 0, 1.3, "black"))
end_sign("2.55", "Ende des Überholverbots", "Fin de l'interdiction de dépasser", "Fine del divieto di sorpasso",
         _all(_at(pg.car_rear, -0.5, 0.05, 0.5, False, "black"), _at(pg.car_rear, 0.5, 0.05, 0.5)))
end_sign("2.56", "Ende des Überholverbots für Lastwagen", "Fin de l'interdiction aux camions de dépasser",
         "Fine del divieto di sorpasso per autocarri",
         _all(_at(pg.lorry_rear, -0.5, 0.05, 0.55, False, "black"), _at(pg.car_rear, 0.5, 0.05, 0.5)))
_add("2.58", "Freie Fahrt", "Fin de toutes les interdictions", "Fine di tutti i divieti", "white", "circle", F.ROUND,
     True, lambda st: frames.disc(st, lambda p: p.line([(-1.3, 1.3), (1.3, -1.3)], 0.42, "black", scaled=False),
                                  fill="white", rim_colour=None, edge="grey"))


def _limit_disc(p: Pen, value: str, ring: str, ink: str):
    p.circle(0, 0, 0.95, ring)
    p.circle(0, 0, 0.76, "white")
    p.text(value, 0, 0, 0.65, ink, max_width=1.15)


def _zone(kind: str, end: bool = False):
    """Upright zone panel: 'ZONE' over the symbol disc; the cancelling panel is grey with black stripes."""
    ring, ink = ("grey", "grey") if end else ("red", "black")

    def content(p: Pen):
        top = p.sub(0, 0.2, 0.9, jitter=False)
        if kind == "30":
            _limit_disc(top, kind, ring, ink)
        else:
            top.circle(0, 0, 0.95, "grey" if end else "blue")
            pg.adult_and_child(top.sub(0, 0, 0.62, jitter=False), "white")
        p.text("ZONE", 0, -0.95, 0.3, ink, max_width=1.6)

    def draw(st):
        d = frames.panel(st, content, aspect=0.5 / 0.7, fill="white", edge="black", content_box=(0.5, 0.7, 0.5))
        if end:
            frames.diagonal_stripes(d, [(0.03, 0.03), (0.97, 0.03), (0.97, 1.37), (0.03, 1.37)], "black", n=5,
                                    spacing=0.05, width=0.016 * st.stroke_scale, angle_deg=-55, centre=(0.5, 0.7))
        return d
    return draw


def _meeting_zone(end: bool = False):
    """Landscape meeting-zone panel: 'ZONE' over a blue field with people, a car and a 20 disc."""
    field, ink = ("grey", "grey") if end else ("blue", "black")

    def content(p: Pen):
        p.text("ZONE", 0, -0.6, 0.22, ink, max_width=0.9)
        p.rect(-0.8, -0.3, 0.8, 0.75, field)
        pg.pedestrian(p.sub(-0.55, 0.3, 0.26), "white")
        pg.car_side(p.sub(-0.1, 0.05, 0.28), "white")
        pg.adult_and_child(p.sub(0.35, 0.05, 0.26), "white")
        _limit_disc(p.sub(0.72, 0.55, 0.3, jitter=False), "20", "grey" if end else "red", ink)

    def draw(st):
        d = frames.panel(st, content, aspect=0.7 / 0.5, fill="white", edge="black",
                         content_box=(0.5, 0.357, 0.42))
        if end:
            frames.diagonal_stripes(d, [(0.03, 0.03), (0.97, 0.03), (0.97, 0.684), (0.03, 0.684)], "black", n=5,
                                    spacing=0.04, width=0.012 * st.stroke_scale, angle_deg=-35,
                                    centre=(0.5, 0.357))
        return d
    return draw


_add("2.53.1", "Ende der Höchstgeschwindigkeit 50 generell", "Fin de la vitesse maximale 50, limite générale",
     "Fine della velocità massima 50, limite generale", "white", "circle", F.ROUND, True, _general_limit(True))
_add("2.59.1-30", "Tempo-30-Zone", "Zone 30", "Zona 30", "red", "rectangle", F.ZONE, True, _zone("30"))
_add("2.59.2-30", "Ende der Tempo-30-Zone", "Fin de la zone 30", "Fine della zona 30", "white", "rectangle", F.ZONE,
     True, _zone("30", end=True))
_add("2.59.3", "Fussgängerzone", "Zone piétonne", "Zona pedonale", "blue", "rectangle", F.ZONE, True,
     _zone("pedestrian"))
_add("2.59.4", "Ende der Fussgängerzone", "Fin de la zone piétonne", "Fine della zona pedonale", "white",
     "rectangle", F.ZONE, True, _zone("pedestrian", end=True))
_add("2.59.5", "Begegnungszone", "Zone de rencontre", "Zona d'incontro", "blue", "rectangle", F.ZONE_WIDE, True,
     _meeting_zone())
_add("2.59.6", "Ende der Begegnungszone", "Fin de la zone de rencontre", "Fine della zona d'incontro", "white",
     "rectangle", F.ZONE_WIDE, True, _meeting_zone(end=True))
mandatory("2.60", "Radweg", "Piste cyclable", "Ciclopista", lambda p: pg.bicycle(p, "white", 0.1))
mandatory("2.61", "Fussweg", "Chemin pour piétons", "Strada pedonale", pg.adult_and_child)
mandatory("2.62", "Reitweg", "Allée d'équitation", "Strada per cavalieri", pg.horse_rider)
mandatory("2.63", "Rad- und Fussweg mit getrennten Verkehrsflächen",
          "Piste cyclable et chemin pour piétons, avec partage de l'aire de circulation",
          "Ciclopista e strada pedonale con divisione dell'area di circolazione",
          _all(lambda p: pg.bicycle(p.sub(-0.66, 0.05, 0.6), "white", 0.14),
               lambda p: p.rect(-0.04, -1.4, 0.04, 1.4, "white"),
               _at(pg.pedestrian, 0.62, 0.0, 0.8, False, "white")))
mandatory("2.63.1", "Gemeinsamer Rad- und Fussweg",
          "Piste cyclable et chemin pour piétons, sans partage de l'aire de circulation",
          "Ciclopista e strada pedonale senza divisione dell'area di circolazione",
          _all(lambda p: pg.bicycle(p.sub(0, 0.58, 0.62), "white", 0.13),
               _at(pg.pedestrian, 0, -0.5, 0.58, False, "white")))
mandatory("2.64", "Busfahrbahn", "Voie réservée aux bus", "Corsia riservata ai bus",
          lambda p: pg.bus_side(p.sub(0, 0, 0.95), "white", "blue"))

# --------------------------------------------------------------------------- 3 priority signs
_add("3.01", "Stop", "Stop", "Stop", "red", "octagon", F.OCTAGON, True,
     lambda st: frames.octagon(st, lambda p: p.text("STOP", 0, 0, 0.62, "white", max_width=1.85)))
_add("3.02", "Kein Vortritt", "Cédez le passage", "Dare precedenza", "red", "triangle-down", F.TRIANGLE, True,
     lambda st: frames.triangle(st, None, down=True))
_add("3.03", "Hauptstrasse", "Route principale", "Strada principale", "yellow", "diamond", F.DIAMOND, False,
     lambda st: frames.diamond(st))


def _end_main_road(st):
    d = frames.diamond(st)
    inner = shapes.inset_convex([(0.5, 0), (1, 0.5), (0.5, 1), (0, 0.5)], 0.1)
    frames.diagonal_stripes(d, inner, "black", n=5, spacing=0.04, width=0.016 * st.stroke_scale, angle_deg=45)
    return d


_add("3.04", "Ende der Hauptstrasse", "Fin de la route principale", "Fine della strada principale", "yellow",
     "diamond", F.DIAMOND, False, _end_main_road)
danger("3.05", "Verzweigung mit Strasse ohne Vortritt", "Intersection avec une route sans priorité",
       "Intersezione con una strada senza precedenza", pg.junction)
danger("3.06", "Verzweigung mit Rechtsvortritt", "Intersection comportant la priorité de droite",
       "Intersezione con precedenza da destra", lambda p: pg.junction(p, kind="x"))
danger("3.07", "Einfahrt von rechts", "Entrée par la droite", "Entrata da destra",
       lambda p: pg.junction(p, kind="merge"))
danger("3.08", "Einfahrt von links", "Entrée par la gauche", "Entrata da sinistra",
       _mirror(pg.junction, kind="merge"))
prohibition("3.09", "Dem Gegenverkehr Vortritt lassen", "Laissez passer les véhicules en sens inverse",
            "Lasciar passare i veicoli provenienti in senso inverso",
            _all(lambda p: p.arrow([(0.38, 0.9), (0.38, -0.9)], 0.2, "red", 0.42, 0.34),
                 lambda p: p.arrow([(-0.38, -0.9), (-0.38, 0.9)], 0.28, "black", 0.5, 0.4)))
info("3.10", "Vortritt vor dem Gegenverkehr", "Priorité par rapport aux véhicules venant en sens inverse",
     "Precedenza rispetto al traffico inverso",
     _all(lambda p: p.arrow([(0.35, 0.95), (0.35, -0.95)], 0.3, "white", 0.5, 0.42),
          lambda p: p.arrow([(-0.4, -0.8), (-0.4, 0.85)], 0.18, "red", 0.36, 0.28)))

# --------------------------------------------------------------------------- 4 information signs
info("4.08", "Einbahnstrasse", "Sens unique", "Senso unico",
     lambda p: p.arrow([(0, 0.95), (0, -0.95)], 0.38, "white", 0.62, 0.55))
info("4.09", "Sackgasse", "Impasse", "Strada senza uscita",
     _all(lambda p: p.rect(-0.22, -0.45, 0.22, 0.95, "white"), lambda p: p.rect(-0.8, -0.95, 0.8, -0.5, "red")))


def _crossing_panel(p: Pen):
    p.poly([(0, -1.1), (1.05, 0.85), (-1.05, 0.85)], "white", 0.08)
    pg.pedestrian(p.sub(0.02, -0.05, 0.42), "black")
    pg.zebra(p.sub(0, 0.05, 0.55, jitter=False), "black", 4, 0.75, 1.2)


_add("4.11", "Standort eines Fussgängerstreifens", "Emplacement d'un passage pour piétons",
     "Ubicazione di un passaggio pedonale", "blue", "rectangle", F.TALL_INFO, False,
     lambda st: frames.panel(st, _crossing_panel, aspect=0.50 / 0.70, content_box=(0.5, 0.5, 0.4)))
info("4.14", "Spital", "Hôpital", "Ospedale", _text("H", 0, 1.3, "white"))
info("4.17", "Parkieren gestattet", "Parking autorisé", "Parcheggio autorizzato", _text("P", 0, 1.4, "white"))


def _tall_parking(sub):
    def content(p: Pen):
        p.text("P", 0, -0.72, 1.05, "white", max_width=1.4)
        sub(p.sub(0, 0.75, 0.85))
    return lambda st: frames.panel(st, content, aspect=0.50 / 0.70, fill="blue", edge="white",
                                   content_box=(0.5, 0.7, 0.36))


_add("4.18", "Parkieren mit Parkscheibe", "Parcage avec disque de stationnement", "Parcheggio con disco",
     "blue", "rectangle", F.TALL_INFO, False, _tall_parking(pg.parking_disc))
_add("4.20", "Parkieren gegen Gebühr", "Parcage payant", "Parcheggio contro pagamento", "blue", "rectangle",
     F.TALL_INFO, False, _tall_parking(pg.parking_meter))


# --------------------------------------------------------------------------- 4 white text panels (generic)
# Place-name and direction panels of secondary roads: their wording varies from panel to panel, so each entry
# stands for its kind (catalogue/text_panels.py); the own drawing shows an example wording.
def _text_panel(lines, aspect: float, bar: bool = False):
    # pen units: 0.45 x the panel's height, so the content spans 0.9 of it
    def content(p: Pen):
        n = len(lines)
        size = 0.55 if n == 1 else 0.4
        for k, line in enumerate(lines):
            p.text(line, 0, (k - (n - 1) / 2) * 0.95, size, "black", max_width=1.9 * aspect)
        if bar:
            p.rect(-2.1 * aspect, -0.09, 2.1 * aspect, 0.09, "black")

    return lambda st: frames.panel(st, content, aspect=aspect, fill="white", edge="black",
                                   content_box=(0.5, 0.5 / aspect, 0.45 / aspect))


def _text_panel_entry(id_, de, fr, it, lines, bar=False):

    w, h = TEXT_PANELS[id_].nominal
    _add(id_, de, fr, it, "white", "rectangle", {"normal": (w, h)}, False, _text_panel(lines, w / h, bar))


_text_panel_entry("4.29", "Ortsbeginn auf Nebenstrassen", "Début de localité sur route secondaire",
                  "Inizio della località su strada secondaria", ["Maur"])
_text_panel_entry("4.30", "Ortsende auf Nebenstrassen", "Fin de localité sur route secondaire",
                  "Fine della località su strada secondaria", ["Maur", "Egg 4 km"], bar=True)
_text_panel_entry("4.33", "Wegweiser für Nebenstrassen", "Indicateur de direction pour routes secondaires",
                  "Indicatore di direzione per strade secondarie", ["Uster"])
