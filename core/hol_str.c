/* hol_str.c - the string table (hol_str.h): English, German, Dutch. */
#include "hol_str.h"

#include <stddef.h>

/* English: the app's words before the table, byte for byte. */
/* The entries a build holds: the web's (HOL_STR_NO_PAGE) ends before the
 * page's words (text.js carries them), so its arrays hold no NULLs for them. */
#ifdef HOL_STR_NO_PAGE
#define HOL__NSTR HOL_S_PAGE_LOADING
#else
#define HOL__NSTR HOL_S_COUNT
#endif

static const char *const hol__en[HOL__NSTR] = {
    [HOL_S_OBJ_FLAG] = "Find the flag",
    [HOL_S_OBJ_KEYS_FMT] = "Keys %d/%d",
    [HOL_S_OBJ_CHEST] = "Bring the keys to the chest",
    [HOL_S_OBJ_EXPLORE] = "Explore",
#ifndef HOL_STR_NO_PAGE /* holonomy render's alone */
    [HOL_S_GUIDE_POLE] = "reach the guide pole",
#endif
    [HOL_S_LESSON_1] = "1/4 Step onto the marked tile ahead",
    [HOL_S_LESSON_2] = "2/4 Walk round the marked tree to this cell",
    [HOL_S_LESSON_3] = "3/4 Use the map: reach the marker",
    [HOL_S_LESSON_4] = "4/4 Find the flag, every cue on",
    [HOL_S_LESSON_1_DONE] = "Well done: one step, one new tile",
    [HOL_S_LESSON_2_DONE] = "Same cell, another tile: that is holonomy",
    [HOL_S_LESSON_3_DONE] = "Found it: the map knows the way",
    [HOL_S_LESSON_4_DONE] = "Flag found: you can play",
    [HOL_S_PATH] = "Map line: the fewest steps to the marker",
    [HOL_S_RINGS] = "Rings on the map: the two tiles of this cell",
    [HOL_S_FIXED] = "Minimap fixed in this study",
    [HOL_S_PAUSED] = "Paused",
    [HOL_S_POINT_CTRL_START] = "Point the controller at the start",
    [HOL_S_POINT_CTRL_CHEST] = "Point the controller at the chest",
    [HOL_S_POINT_CTRL_FLAG] = "Point the controller at the flag",
    [HOL_S_POINT_FACE_START] = "Turn to face the start",
    [HOL_S_POINT_FACE_CHEST] = "Turn to face the chest",
    [HOL_S_POINT_FACE_FLAG] = "Turn to face the flag",
    [HOL_S_TIME_UP_FMT] = "Time up: %d steps, best %d, %ld:%02ld",
    [HOL_S_TUTORIAL_DONE_FMT] = "Tutorial done: %d steps, %ld:%02ld",
    [HOL_S_DONE_FMT] = "Done: %d steps, best %d, %ld:%02ld",
    [HOL_S_DEVICE_LOST] = "Controller lost",
    [HOL_S_OUTSIDE] = "Outside the room: step back in",
    [HOL_S_DEVICE_BACK] = "Plug it back in, or press a key",
    [HOL_S_SMALL_AREA_FMT] = "Play area under %.12s m: mind the edges",
    [HOL_S_MOVE_KEYBOARD] = "W/S/A/D: WALK, ARROWS: TURN",
    [HOL_S_MOVE_GAMEPAD] = "LEFT STICK: WALK, RIGHT STICK: TURN",
    [HOL_S_MOVE_ROOM] = "WALK IN YOUR ROOM",
    [HOL_S_DO_FINISH] = "finish",
    [HOL_S_DO_BEGIN] = "begin",
    [HOL_S_DO_QUIT] = "quit",
    [HOL_S_DO_CONFIRM] = "confirm",
    [HOL_S_DO_RESUME] = "resume",
    [HOL_S_DO_RESTART] = "restart",
    [HOL_S_DO_ANSWER] = "answer",
    [HOL_S_DO_NEXT_LEVEL] = "next level",
    [HOL_S_DO_AGAIN] = "again",
    [HOL_S_DO_MENU] = "menu",
    [HOL_S_DO_MAP] = "map on the HUD, in the hand, off",
    [HOL_S_STEPS_FMT] = "STEPS %d",
    [HOL_S_TIME_OF_FMT] = "TIME %ld:%02ld OF %ld:%02ld",
    [HOL_S_TIME_FMT] = "TIME %ld:%02ld",
    [HOL_S_TILE_FMT] = "TILE %.40s",
    [HOL_S_CELL_FMT] = "CELL %d,%d NORTH %d",
    [HOL_S_CAP_START] = "[Sound: chime, the level begins]",
    [HOL_S_CAP_KEY] = "[Sound: chime, a key collected]",
    [HOL_S_CAP_CHEST] = "[Sound: chime, the chest opens]",
    [HOL_S_CAP_FLAG] = "[Sound: chime, the flag reached]",
    [HOL_S_CAP_BEACON] = "[Sound: beacons pip at the goals]",
    [HOL_S_PAUSE_UNFOCUSED] = "the window is not focused",
    [HOL_S_PAUSE_HEADSET_OFF] = "the headset is off",
    [HOL_S_PAUSE_SYSTEM_MENU] = "a system menu is over the game",
    [HOL_S_PAUSE_PAD_GONE] = "the game controller went away",
    [HOL_S_PAUSE_MENU] = "the menu is open",
    [HOL_S_FIT_FMT] = "Room %d x %d cells of %s m fits your %s x %s m play area",
    [HOL_S_FIT_SMALL_FMT] = "Your %s x %s m play area is smaller than the smallest room (3 x 3 "
                            "cells of 0.5 m and %s m clear): playing 3 x 3 cells of 0.5 m, keep "
                            "to the middle",
#ifndef HOL_STR_NO_PAGE /* the web build: text.js carries them */
    [HOL_S_PAGE_LOADING] = "Loading…",
    [HOL_S_PAGE_OK] = "OK",
    [HOL_S_PAGE_BACK] = "Back",
    [HOL_S_PAGE_MENU] = "Menu",
    [HOL_S_PAGE_MAP] = "Map",
    [HOL_S_PAGE_VR_ENTER] = "Enter VR",
    [HOL_S_PAGE_VR_EXIT] = "Exit VR",
    [HOL_S_PAGE_VR_HTTPS] = "VR needs https:// or localhost",
    [HOL_S_PAGE_VR_HTTPS_WHY] = "WebXR runs only on a secure page: open it with https://, or from localhost (docs/web.md)",
    [HOL_S_PAGE_VR_NONE] = "No VR in this browser",
    [HOL_S_PAGE_VR_NONE_WHY] = "this browser has no WebXR",
    [HOL_S_PAGE_VR_NO_HEADSET] = "No VR headset found",
    [HOL_S_PAGE_VR_NO_HEADSET_WHY] = "connect a headset (or open the page in its browser) and reload",
    [HOL_S_PAGE_AGAIN] = "Play again",
    [HOL_S_PAGE_FIT] = "Play the room that fits your play area",
    [HOL_S_PAGE_FILE] = "Level file…",
    [HOL_S_PAGE_FILE_WHY] = "Play a level file (SPEC section 5)",
    [HOL_S_PAGE_LOGS] = "Logs",
    [HOL_S_PAGE_HELP] = "Click the view to look with the mouse · W/S/A/D walk · arrows turn · P menu · M map · R restart · Enter next · F2 frame time · Q quit",
    [HOL_S_PAGE_NO_LOGS] = "No logs yet.",
    [HOL_S_PAGE_CLEAR] = "Delete all logs",
    [HOL_S_PAGE_CLEAR_ASK] = "Delete every log and recording kept in this browser?",
    [HOL_S_PAGE_BYTES] = "bytes",
    [HOL_S_PAGE_PLAYING] = "Playing",
    [HOL_S_PAGE_PLAYING_LEVEL] = "Playing %s",
    [HOL_S_PAGE_IN_VR] = "In VR",
    [HOL_S_PAGE_PAUSED] = "Paused: %s",
    [HOL_S_PAGE_OVER] = "Session over: the logs are kept in this browser (Logs).",
    [HOL_S_PAGE_FAILED] = "Failed: %s",
    [HOL_S_PAGE_WARNING] = "Warning: %s",
    [HOL_S_PAGE_VR_FAILED] = "VR failed: %s",
    [HOL_S_PAGE_NO_STUDY] = "Cannot load the study: %s",
    [HOL_S_PAGE_NO_LEVEL] = "Cannot load the level: %s",
    [HOL_S_PAGE_NO_GAME] = "cannot load the game",
    [HOL_S_PAGE_NO_START] = "cannot start the game",
#endif
};

/* German (du, as a class is spoken to). The controls keep the names
 * printed on them (ENTER, A, TRIGGER: core/hol_prompt.c). */
static const char *const hol__de[HOL__NSTR] = {
    [HOL_S_OBJ_FLAG] = "Finde die Fahne",
    [HOL_S_OBJ_KEYS_FMT] = "Schlüssel %d/%d",
    [HOL_S_OBJ_CHEST] = "Bring die Schlüssel zur Truhe",
    [HOL_S_OBJ_EXPLORE] = "Erkunde den Wald",
#ifndef HOL_STR_NO_PAGE /* holonomy render's alone */
    [HOL_S_GUIDE_POLE] = "geh zum Leitpfosten",
#endif
    [HOL_S_LESSON_1] = "1/4 Tritt auf die markierte Kachel vor dir",
    [HOL_S_LESSON_2] = "2/4 Um den markierten Baum in diese Zelle",
    [HOL_S_LESSON_3] = "3/4 Nutze die Karte: zur Markierung",
    [HOL_S_LESSON_4] = "4/4 Finde die Fahne, alle Hilfen an",
    [HOL_S_LESSON_1_DONE] = "Gut: ein Schritt, eine neue Kachel",
    [HOL_S_LESSON_2_DONE] = "Dieselbe Zelle, andere Kachel: Holonomie",
    [HOL_S_LESSON_3_DONE] = "Gefunden: die Karte kennt den Weg",
    [HOL_S_LESSON_4_DONE] = "Fahne gefunden: du kannst spielen",
    [HOL_S_PATH] = "Kartenlinie: der kürzeste Weg zur Markierung",
    [HOL_S_RINGS] = "Ringe: die zwei Kacheln dieser Zelle",
    [HOL_S_FIXED] = "Karte in dieser Studie fest",
    [HOL_S_PAUSED] = "Pause",
    [HOL_S_POINT_CTRL_START] = "Zeig mit dem Controller auf den Start",
    [HOL_S_POINT_CTRL_CHEST] = "Zeig mit dem Controller auf die Truhe",
    [HOL_S_POINT_CTRL_FLAG] = "Zeig mit dem Controller auf die Fahne",
    [HOL_S_POINT_FACE_START] = "Dreh dich zum Start",
    [HOL_S_POINT_FACE_CHEST] = "Dreh dich zur Truhe",
    [HOL_S_POINT_FACE_FLAG] = "Dreh dich zur Fahne",
    [HOL_S_TIME_UP_FMT] = "Zeit um: %d Schritte, Minimum %d, %ld:%02ld",
    [HOL_S_TUTORIAL_DONE_FMT] = "Einführung fertig: %d Schritte, %ld:%02ld",
    [HOL_S_DONE_FMT] = "Fertig: %d Schritte, Minimum %d, %ld:%02ld",
    [HOL_S_DEVICE_LOST] = "Controller getrennt",
    [HOL_S_OUTSIDE] = "Außerhalb des Raums: tritt zurück",
    [HOL_S_DEVICE_BACK] = "Wieder anstecken oder eine Taste drücken",
    [HOL_S_SMALL_AREA_FMT] = "Spielfläche unter %.12s m: Vorsicht am Rand",
    [HOL_S_MOVE_KEYBOARD] = "W/S/A/D: GEHEN, PFEILE: DREHEN",
    [HOL_S_MOVE_GAMEPAD] = "LINKER STICK: GEHEN, RECHTER: DREHEN",
    [HOL_S_MOVE_ROOM] = "GEH IN DEINEM RAUM",
    [HOL_S_DO_FINISH] = "beenden",
    [HOL_S_DO_BEGIN] = "anfangen",
    [HOL_S_DO_QUIT] = "aufhören",
    [HOL_S_DO_CONFIRM] = "bestätigen",
    [HOL_S_DO_RESUME] = "weiter",
    [HOL_S_DO_RESTART] = "neu starten",
    [HOL_S_DO_ANSWER] = "antworten",
    [HOL_S_DO_NEXT_LEVEL] = "nächstes Level",
    [HOL_S_DO_AGAIN] = "nochmal",
    [HOL_S_DO_MENU] = "Menü",
    [HOL_S_DO_MAP] = "Karte im HUD, in der Hand, aus",
    [HOL_S_STEPS_FMT] = "SCHRITTE %d",
    [HOL_S_TIME_OF_FMT] = "ZEIT %ld:%02ld VON %ld:%02ld",
    [HOL_S_TIME_FMT] = "ZEIT %ld:%02ld",
    [HOL_S_TILE_FMT] = "KACHEL %.40s",
    [HOL_S_CELL_FMT] = "ZELLE %d,%d NORD %d",
    [HOL_S_CAP_START] = "[Ton: Glocke, das Level beginnt]",
    [HOL_S_CAP_KEY] = "[Ton: Glocke, ein Schlüssel gefunden]",
    [HOL_S_CAP_CHEST] = "[Ton: Glocke, die Truhe geht auf]",
    [HOL_S_CAP_FLAG] = "[Ton: Glocke, die Fahne erreicht]",
    [HOL_S_CAP_BEACON] = "[Ton: Signale piepen an den Zielen]",
    [HOL_S_PAUSE_UNFOCUSED] = "das Fenster ist nicht im Fokus",
    [HOL_S_PAUSE_HEADSET_OFF] = "die Brille ist abgesetzt",
    [HOL_S_PAUSE_SYSTEM_MENU] = "ein Systemmenü ist offen",
    [HOL_S_PAUSE_PAD_GONE] = "der Controller ist weg",
    [HOL_S_PAUSE_MENU] = "das Menü ist offen",
    [HOL_S_FIT_FMT] = "Raum %d x %d Zellen zu %s m passt in deine %s x %s m Spielfläche",
    [HOL_S_FIT_SMALL_FMT] = ("Deine %s x %s m Spielfläche ist zu klein für 3 x 3 Zellen zu "
                             "0.5 m und %s m Rand: bleib in der Mitte"),
#ifndef HOL_STR_NO_PAGE /* the web build: text.js carries them */
    [HOL_S_PAGE_LOADING] = "Lädt…",
    [HOL_S_PAGE_OK] = "OK",
    [HOL_S_PAGE_BACK] = "Zurück",
    [HOL_S_PAGE_MENU] = "Menü",
    [HOL_S_PAGE_MAP] = "Karte",
    [HOL_S_PAGE_VR_ENTER] = "VR starten",
    [HOL_S_PAGE_VR_EXIT] = "VR beenden",
    [HOL_S_PAGE_VR_HTTPS] = "VR braucht https:// oder localhost",
    [HOL_S_PAGE_VR_HTTPS_WHY] = "WebXR läuft nur auf einer sicheren Seite: öffne sie mit https:// oder von localhost (docs/web.md)",
    [HOL_S_PAGE_VR_NONE] = "Kein VR in diesem Browser",
    [HOL_S_PAGE_VR_NONE_WHY] = "dieser Browser hat kein WebXR",
    [HOL_S_PAGE_VR_NO_HEADSET] = "Keine VR-Brille gefunden",
    [HOL_S_PAGE_VR_NO_HEADSET_WHY] = "schließe eine Brille an (oder öffne die Seite in ihrem Browser) und lade neu",
    [HOL_S_PAGE_AGAIN] = "Nochmal spielen",
    [HOL_S_PAGE_FIT] = "Den Raum spielen, der in deine Spielfläche passt",
    [HOL_S_PAGE_FILE] = "Level-Datei…",
    [HOL_S_PAGE_FILE_WHY] = "Eine Level-Datei spielen (SPEC Abschnitt 5)",
    [HOL_S_PAGE_LOGS] = "Protokolle",
    [HOL_S_PAGE_HELP] = "Klick ins Bild, um mit der Maus zu schauen · W/S/A/D gehen · Pfeile drehen · P Menü · M Karte · R neu starten · Enter weiter · F2 Bildzeit · Q beenden",
    [HOL_S_PAGE_NO_LOGS] = "Noch keine Protokolle.",
    [HOL_S_PAGE_CLEAR] = "Alle Protokolle löschen",
    [HOL_S_PAGE_CLEAR_ASK] = "Alle Protokolle und Aufnahmen in diesem Browser löschen?",
    [HOL_S_PAGE_BYTES] = "Bytes",
    [HOL_S_PAGE_PLAYING] = "Im Spiel",
    [HOL_S_PAGE_PLAYING_LEVEL] = "Im Spiel: %s",
    [HOL_S_PAGE_IN_VR] = "In VR",
    [HOL_S_PAGE_PAUSED] = "Pause: %s",
    [HOL_S_PAGE_OVER] = "Sitzung beendet: die Protokolle bleiben in diesem Browser (Protokolle).",
    [HOL_S_PAGE_FAILED] = "Fehler: %s",
    [HOL_S_PAGE_WARNING] = "Warnung: %s",
    [HOL_S_PAGE_VR_FAILED] = "VR fehlgeschlagen: %s",
    [HOL_S_PAGE_NO_STUDY] = "Die Studie lädt nicht: %s",
    [HOL_S_PAGE_NO_LEVEL] = "Das Level lädt nicht: %s",
    [HOL_S_PAGE_NO_GAME] = "das Spiel lädt nicht",
    [HOL_S_PAGE_NO_START] = "das Spiel startet nicht",
#endif
};

#ifndef HOL_STR_NO_NL /* a build without Dutch (the web's: Makefile WEB_LANGS) */
/* Dutch (je, as a class is spoken to). */
static const char *const hol__nl[HOL__NSTR] = {
    [HOL_S_OBJ_FLAG] = "Vind de vlag",
    [HOL_S_OBJ_KEYS_FMT] = "Sleutels %d/%d",
    [HOL_S_OBJ_CHEST] = "Breng de sleutels naar de kist",
    [HOL_S_OBJ_EXPLORE] = "Verken het bos",
#ifndef HOL_STR_NO_PAGE /* holonomy render's alone */
    [HOL_S_GUIDE_POLE] = "loop naar de paal",
#endif
    [HOL_S_LESSON_1] = "1/4 Stap op de gemarkeerde tegel voor je",
    [HOL_S_LESSON_2] = "2/4 Loop om de gemarkeerde boom naar deze cel",
    [HOL_S_LESSON_3] = "3/4 Gebruik de kaart: naar de marker",
    [HOL_S_LESSON_4] = "4/4 Vind de vlag, alle hulp aan",
    [HOL_S_LESSON_1_DONE] = "Goed: één stap, één nieuwe tegel",
    [HOL_S_LESSON_2_DONE] = "Zelfde cel, andere tegel: dat is holonomie",
    [HOL_S_LESSON_3_DONE] = "Gevonden: de kaart kent de weg",
    [HOL_S_LESSON_4_DONE] = "Vlag gevonden: je kunt spelen",
    [HOL_S_PATH] = "Lijn op de kaart: de kortste weg naar de marker",
    [HOL_S_RINGS] = "Ringen: de twee tegels van deze cel",
    [HOL_S_FIXED] = "Kaart staat vast in dit onderzoek",
    [HOL_S_PAUSED] = "Pauze",
    [HOL_S_POINT_CTRL_START] = "Wijs met de controller naar de start",
    [HOL_S_POINT_CTRL_CHEST] = "Wijs met de controller naar de kist",
    [HOL_S_POINT_CTRL_FLAG] = "Wijs met de controller naar de vlag",
    [HOL_S_POINT_FACE_START] = "Draai je naar de start",
    [HOL_S_POINT_FACE_CHEST] = "Draai je naar de kist",
    [HOL_S_POINT_FACE_FLAG] = "Draai je naar de vlag",
    [HOL_S_TIME_UP_FMT] = "Tijd op: %d stappen, best %d, %ld:%02ld",
    [HOL_S_TUTORIAL_DONE_FMT] = "Uitleg klaar: %d stappen, %ld:%02ld",
    [HOL_S_DONE_FMT] = "Klaar: %d stappen, best %d, %ld:%02ld",
    [HOL_S_DEVICE_LOST] = "Controller kwijt",
    [HOL_S_OUTSIDE] = "Buiten de kamer: stap terug",
    [HOL_S_DEVICE_BACK] = "Sluit hem weer aan, of druk op een toets",
    [HOL_S_SMALL_AREA_FMT] = "Speelruimte onder %.12s m: let op de randen",
    [HOL_S_MOVE_KEYBOARD] = "W/S/A/D: LOPEN, PIJLEN: DRAAIEN",
    [HOL_S_MOVE_GAMEPAD] = "LINKER STICK: LOPEN, RECHTER: DRAAIEN",
    [HOL_S_MOVE_ROOM] = "LOOP IN JE KAMER",
    [HOL_S_DO_FINISH] = "afsluiten",
    [HOL_S_DO_BEGIN] = "beginnen",
    [HOL_S_DO_QUIT] = "stoppen",
    [HOL_S_DO_CONFIRM] = "bevestigen",
    [HOL_S_DO_RESUME] = "verder",
    [HOL_S_DO_RESTART] = "opnieuw beginnen",
    [HOL_S_DO_ANSWER] = "antwoorden",
    [HOL_S_DO_NEXT_LEVEL] = "volgend level",
    [HOL_S_DO_AGAIN] = "nog eens",
    [HOL_S_DO_MENU] = "menu",
    [HOL_S_DO_MAP] = "kaart in de HUD, in de hand, uit",
    [HOL_S_STEPS_FMT] = "STAPPEN %d",
    [HOL_S_TIME_OF_FMT] = "TIJD %ld:%02ld VAN %ld:%02ld",
    [HOL_S_TIME_FMT] = "TIJD %ld:%02ld",
    [HOL_S_TILE_FMT] = "TEGEL %.40s",
    [HOL_S_CELL_FMT] = "CEL %d,%d NOORD %d",
    [HOL_S_CAP_START] = "[Geluid: bel, het level begint]",
    [HOL_S_CAP_KEY] = "[Geluid: bel, een sleutel gevonden]",
    [HOL_S_CAP_CHEST] = "[Geluid: bel, de kist gaat open]",
    [HOL_S_CAP_FLAG] = "[Geluid: bel, de vlag bereikt]",
    [HOL_S_CAP_BEACON] = "[Geluid: bakens piepen bij de doelen]",
    [HOL_S_PAUSE_UNFOCUSED] = "het venster heeft geen focus",
    [HOL_S_PAUSE_HEADSET_OFF] = "de bril is af",
    [HOL_S_PAUSE_SYSTEM_MENU] = "een systeemmenu ligt over het spel",
    [HOL_S_PAUSE_PAD_GONE] = "de controller is weg",
    [HOL_S_PAUSE_MENU] = "het menu is open",
    [HOL_S_FIT_FMT] = "Kamer van %d x %d cellen van %s m past in je speelruimte van %s x %s m",
    [HOL_S_FIT_SMALL_FMT] = "Je speelruimte van %s x %s m is kleiner dan de kleinste kamer (3 x 3 "
                            "cellen van 0.5 m en %s m vrij): je speelt 3 x 3 cellen van 0.5 m, "
                            "blijf in het midden",
#ifndef HOL_STR_NO_PAGE /* the web build: text.js carries them */
    [HOL_S_PAGE_LOADING] = "Laden…",
    [HOL_S_PAGE_OK] = "OK",
    [HOL_S_PAGE_BACK] = "Terug",
    [HOL_S_PAGE_MENU] = "Menu",
    [HOL_S_PAGE_MAP] = "Kaart",
    [HOL_S_PAGE_VR_ENTER] = "VR starten",
    [HOL_S_PAGE_VR_EXIT] = "VR verlaten",
    [HOL_S_PAGE_VR_HTTPS] = "VR heeft https:// of localhost nodig",
    [HOL_S_PAGE_VR_HTTPS_WHY] = "WebXR werkt alleen op een veilige pagina: open hem met https://, of vanaf localhost (docs/web.md)",
    [HOL_S_PAGE_VR_NONE] = "Geen VR in deze browser",
    [HOL_S_PAGE_VR_NONE_WHY] = "deze browser heeft geen WebXR",
    [HOL_S_PAGE_VR_NO_HEADSET] = "Geen VR-bril gevonden",
    [HOL_S_PAGE_VR_NO_HEADSET_WHY] = "sluit een bril aan (of open de pagina in zijn browser) en laad opnieuw",
    [HOL_S_PAGE_AGAIN] = "Nog eens spelen",
    [HOL_S_PAGE_FIT] = "Speel de kamer die in je speelruimte past",
    [HOL_S_PAGE_FILE] = "Levelbestand…",
    [HOL_S_PAGE_FILE_WHY] = "Een levelbestand spelen (SPEC paragraaf 5)",
    [HOL_S_PAGE_LOGS] = "Logs",
    [HOL_S_PAGE_HELP] = "Klik in het beeld om met de muis te kijken · W/S/A/D lopen · pijlen draaien · P menu · M kaart · R opnieuw · Enter verder · F2 beeldtijd · Q stoppen",
    [HOL_S_PAGE_NO_LOGS] = "Nog geen logs.",
    [HOL_S_PAGE_CLEAR] = "Alle logs wissen",
    [HOL_S_PAGE_CLEAR_ASK] = "Alle logs en opnamen in deze browser wissen?",
    [HOL_S_PAGE_BYTES] = "bytes",
    [HOL_S_PAGE_PLAYING] = "Aan het spelen",
    [HOL_S_PAGE_PLAYING_LEVEL] = "Aan het spelen: %s",
    [HOL_S_PAGE_IN_VR] = "In VR",
    [HOL_S_PAGE_PAUSED] = "Pauze: %s",
    [HOL_S_PAGE_OVER] = "Sessie voorbij: de logs blijven in deze browser (Logs).",
    [HOL_S_PAGE_FAILED] = "Mislukt: %s",
    [HOL_S_PAGE_WARNING] = "Waarschuwing: %s",
    [HOL_S_PAGE_VR_FAILED] = "VR mislukt: %s",
    [HOL_S_PAGE_NO_STUDY] = "Het onderzoek laadt niet: %s",
    [HOL_S_PAGE_NO_LEVEL] = "Het level laadt niet: %s",
    [HOL_S_PAGE_NO_GAME] = "het spel laadt niet",
    [HOL_S_PAGE_NO_START] = "het spel start niet",
#endif
};
#define HOL__NL hol__nl
#else
#define HOL__NL NULL
#endif

static const char *const *const hol__lang[HOL_LANG_COUNT] = {hol__en, hol__de, HOL__NL};
static const char hol__code[HOL_LANG_COUNT][3] = {"en", "de", "nl"};

const char *hol_str(int lang, hol_str_id id)
{
    if (lang < 0 || lang >= HOL_LANG_COUNT || !hol__lang[lang])
        lang = HOL_LANG_EN; /* and a language this build leaves out */
    if ((int)id < 0 || id >= HOL__NSTR)
        return "";
    const char *s = hol__lang[lang][id];
    return s ? s : ""; /* a missing entry (tests/test_str.c finds none) */
}

int hol_str_cap(hol_str_id id)
{
    if (id >= HOL_S_DEVICE_BACK && id <= HOL_S_DO_MAP)
        return 60; /* HOL_APP_HINT_MAX: the prompt's line */
    if (id >= HOL_S_PAGE_FIRST)
        return 256; /* the page's: no buffer of the app's */
    return 48;     /* HOL_APP_TEXT_MAX */
}

static int hol__lower(int c)
{
    return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c;
}

int hol_lang_parse(const char *tag)
{
    if (!tag)
        return -1;
    for (int l = 0; l < HOL_LANG_COUNT; l++)
        if (hol__lang[l] && hol__lower(tag[0]) == hol__code[l][0] && tag[0] &&
            hol__lower(tag[1]) == hol__code[l][1] && tag[1] &&
            (tag[2] == 0 || tag[2] == '-' || tag[2] == '_'))
            return l;
    return -1;
}

const char *hol_lang_code(int lang)
{
    return hol__code[lang >= 0 && lang < HOL_LANG_COUNT ? lang : HOL_LANG_EN];
}
