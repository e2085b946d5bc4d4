#!/usr/bin/env python3
"""Fills app/gui/i18n/raystep_it.ts with the Italian of every string (the lecture's language).
Run after lupdate has added new strings: it keeps the table below as the one source of truth and
reports any string it has no translation for. The lecture's help texts are not here: they are
Markdown files per language in app/gui/texts/."""
import pathlib
import sys
import xml.etree.ElementTree as ET

IT = {
    "DDA step": "passo del DDA",
    "primitive test": "test di una primitiva",
    "mailbox skip": "saltata dalla mailbox",
    "node enter": "ingresso in un nodo",
    "ray begin": "inizio di un raggio",
    "hit": "intersezione",
    "split chosen": "split scelto",
    "raystep - compare midpoint, median and SAH": "raystep - confronto tra midpoint, mediana e SAH",
    "build ms": "costruzione (ms)",
    "nodes": "nodi",
    "leaves": "foglie",
    "max depth": "profondità massima",
    "references": "riferimenti",
    "SAH cost": "costo SAH",
    "ray: tests": "raggio: test",
    "ray: nodes visited": "raggio: nodi visitati",
    "ray: events": "raggio: eventi",
    "midpoint": "midpoint",
    "median": "mediana",
    "SAH": "SAH",
    "step (the same ray in each)": "passo (lo stesso raggio in ognuno)",
    "Rendering...": "Rendering in corso...",
    "The image view shows 3D scenes.": "La vista immagine mostra le scene 3D.",
    "Primitive tests per pixel (dark: few, bright: many)":
        "Test di primitive per pixel (scuro: pochi, chiaro: molti)",
    "Ray tracing (raystep): click a pixel to trace it":
        "Ray tracing (raystep): clicca un pixel per tracciarlo",
    "raystep": "raystep",
    "First event (Home)": "Primo evento (Home)",
    "Step back (Left)": "Passo indietro (Sinistra)",
    "Play / pause (Space)": "Avvia / pausa (Spazio)",
    "Step forward (Right)": "Passo avanti (Destra)",
    "next": "successivo",
    "Jump to the next event of this kind (N)": "Salta al prossimo evento di questo tipo (N)",
    "speed": "velocità",
    " /s": " /s",
    "Inspector": "Ispettore",
    "Filter events (e.g. cell, test, mailbox)": "Filtra gli eventi (es. cell, test, mailbox)",
    "Events": "Eventi",
    "Cancel": "Annulla",
    "Render cancelled": "Rendering annullato",
    "Rendered in %1 ms; click a pixel to trace it":
        "Rendering in %1 ms; clicca un pixel per tracciarlo",
    "Pixel (%1, %2): %3 events recorded": "Pixel (%1, %2): %3 eventi registrati",
    "&File": "&File",
    "&Open scene...": "&Apri scena...",
    "Export &trace...": "Esporta &traccia...",
    "Export screenshot of the &window...": "Esporta screenshot della &finestra...",
    "window": "finestra",
    "Export screenshot of the &2D view...": "Esporta screenshot della vista &2D...",
    "2D view": "vista 2D",
    "Export screenshot of the &3D view...": "Esporta screenshot della vista &3D...",
    "3D view": "vista 3D",
    "&Quit": "&Esci",
    "&Replay": "&Riproduzione",
    "Step &forward": "Passo &avanti",
    "Step &back": "Passo &indietro",
    "&Play / pause": "A&vvia / pausa",
    "&Next event of the kind": "&Prossimo evento del tipo",
    "Replay the &build (candidates, splits, leaves)":
        "Riproduci la &costruzione (candidati, split, foglie)",
    "Replay the &example ray": "Riproduci il raggio d'&esempio",
    "&First event": "P&rimo evento",
    "&Last event": "&Ultimo evento",
    "&View": "&Vista",
    "&Compare midpoint, median and SAH...": "&Confronta midpoint, mediana e SAH...",
    "&Heat map of primitive tests": "&Mappa di calore dei test di primitive",
    "&Reset 3D camera": "&Reimposta la camera 3D",
    "Cannot open the scene": "Impossibile aprire la scena",
    "Rendering %1...": "Rendering di %1...",
    "Loading %1 and building its %2...": "Caricamento di %1 e costruzione del suo %2...",
    "Opening %1 cancelled": "Apertura di %1 annullata",
    "raystep - %1": "raystep - %1",
    "Compare": "Confronto",
    "Compare mode shows the lecture's 2D scenes; for a 3D scene, raystep-cli compare prints the "
    "same table.":
        "Il confronto mostra le scene 2D della lezione; per una scena 3D, raystep-cli compare "
        "stampa la stessa tabella.",
    "%1 / %2": "%1 / %2",
    "Open scene": "Apri scena",
    "Scenes (*.json)": "Scene (*.json)",
    "Screenshot of the %1": "Screenshot della %1",
    "PNG images (*.png)": "Immagini PNG (*.png)",
    "Cannot save": "Impossibile salvare",
    "Could not write %1": "Impossibile scrivere %1",
    "Export trace": "Esporta traccia",
    "Trace files (*.json)": "File di traccia (*.json)",
    "The 2D view shows the lecture's 2D scenes.": "La vista 2D mostra le scene 2D della lezione.",
    "SAH cost of each candidate (X blue, Y purple; dashed: leaf)":
        "Costo SAH di ogni candidato (X blu, Y viola; tratteggio: foglia)",
    "The 3D view shows 3D scenes.": "La vista 3D mostra le scene 3D.",
    "Rasterization (VTK, OpenGL): the scene and the recorded rays":
        "Rasterizzazione (VTK, OpenGL): la scena e i raggi registrati",
    "Open a lesson": "Apri una lezione",
    "< Step": "< Passo",
    "Step >": "Passo >",
    "Previous step (Page Up)": "Passo precedente (Pagina su)",
    "Next step (Page Down)": "Passo successivo (Pagina giù)",
    "Exercise": "Esercizio",
    "Check": "Verifica",
    "Hint": "Suggerimento",
    "Show answer": "Mostra la risposta",
    "Run the sweep": "Esegui lo sweep",
    "Lessons...": "Lezioni...",
    "Step": "Passo",
    "Step %1 / %2": "Passo %1 / %2",
    "Exercise %1 / %2%3": "Esercizio %1 / %2%3",
    " (solved)": " (risolto)",
    "X,Y (or click the cell in the 2D view)": "X,Y (o clicca la cella nella vista 2D)",
    "a number, e.g. 1.25": "un numero, ad es. 1,25",
    "a whole number": "un numero intero",
    "hit T, or miss": "hit T, oppure miss",
    "hit or miss": "hit oppure miss",
    "Cannot read that answer: %1.": "Risposta non leggibile: %1.",
    "Right. %1": "Giusto. %1",
    "Not right. The answer is %1: %2": "Non è giusto. La risposta è %1: %2",
    "Not right yet (try %1 of 3). Step the replay and look at the inspector, or ask for a hint.":
        "Non ancora giusto (tentativo %1 di 3). Fai avanzare la riproduzione e guarda "
        "l'ispettore, oppure chiedi un suggerimento.",
    "Hint: %1": "Suggerimento: %1",
    "Answer: %1. %2": "Risposta: %1. %2",
    "cells/axis": "celle/asse",
    "cells": "celle",
    "refs": "riferimenti",
    "tests/ray": "test/raggio",
    "cells/ray": "celle/raggio",
    "skips/ray": "salti/raggio",
    "trace ms": "tracciamento (ms)",
    "Progress file unreadable, kept as %1: %2": "File dei progressi illeggibile, conservato come %1: %2",
    "Export screenshot of the &image view...": "Esporta screenshot della vista &immagine...",
    "image view": "vista immagine",
    "Export &progress report...": "Esporta il resoconto dei &progressi...",
    "&Lessons": "&Lezioni",
    "&Built-in lessons": "Lezioni &incluse",
    "Building the midpoint, median and SAH trees...":
        "Costruzione degli alberi midpoint, mediana e SAH...",
    "Compare cancelled": "Confronto annullato",
    "Open lesson &file...": "Apri &file di lezione...",
    "Open lesson": "Apri lezione",
    "Lessons (*.json)": "Lezioni (*.json)",
    "&Lecturer mode (show answers)": "Modalità &docente (mostra le risposte)",
    "Cannot open the lesson": "Impossibile aprire la lezione",
    "raystep - lesson %1: %2": "raystep - lezione %1: %2",
    "Cannot save the progress to %1": "Impossibile salvare i progressi in %1",
    "Export progress report": "Esporta il resoconto dei progressi",
    "Markdown (*.md)": "Markdown (*.md)",
    "Tracing the same rays at %1 grid resolutions...":
        "Tracciamento degli stessi raggi con %1 risoluzioni della griglia...",
}

path = pathlib.Path(__file__).with_name("raystep_it.ts")
tree = ET.parse(path)
missing = []
for message in tree.getroot().iter("message"):
    source = message.find("source").text
    translation = message.find("translation")
    if source in IT:
        translation.text = IT[source]
        translation.attrib.pop("type", None)
    else:
        missing.append(source)
tree.write(path, encoding="utf-8", xml_declaration=True)
if missing:
    print("no Italian for:", *missing, sep="\n  ")
    sys.exit(1)
print("all", sum(1 for _ in tree.getroot().iter("message")), "strings translated")
