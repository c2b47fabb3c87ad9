/* hol_str.c - the string table (hol_str.h): English, German, Dutch. */
#include "hol_str.h"

#include <stddef.h>

/* The entries a build holds: the web's (HOL_STR_NO_PAGE) ends before the
 * page's words (text.js carries them), and leaves out what only
 * `holonomy render` says. */
#ifdef HOL_STR_NO_PAGE
#define HOL__NSTR HOL_S_PAGE_LOADING
#else
#define HOL__NSTR HOL_S_COUNT
#endif
/* A build without Dutch (the web's: Makefile WEB_LANGS) keeps no Dutch
 * text: hol_str reads English for it, hol_lang_parse does not take "nl". */
#ifdef HOL_STR_NO_NL
#define HOL__NL(s) NULL
#else
#define HOL__NL(s) s
#endif

/* One row an id, in the order of enum hol_lang: English (the app's words
 * before the table, byte for byte), German (du, as a class is spoken to),
 * Dutch (je). The controls keep the names printed on them (ENTER, A,
 * TRIGGER: core/hol_prompt.c). */
static const char *const hol__rows[HOL__NSTR][HOL_LANG_COUNT] = {
    [HOL_S_OBJ_FLAG] = {"Find the flag",
                        "Finde die Fahne",
                        HOL__NL("Vind de vlag")},
    [HOL_S_OBJ_KEYS_FMT] = {"Keys %d/%d",
                            "Schlüssel %d/%d",
                            HOL__NL("Sleutels %d/%d")},
    [HOL_S_OBJ_CHEST] = {"Bring the keys to the chest",
                         "Bring die Schlüssel zur Truhe",
                         HOL__NL("Breng de sleutels naar de kist")},
    [HOL_S_OBJ_EXPLORE] = {"Explore",
                           "Erkunde den Wald",
                           HOL__NL("Verken het bos")},
#ifndef HOL_STR_NO_PAGE /* holonomy render's alone */
    [HOL_S_GUIDE_POLE] = {"reach the guide pole",
                          "geh zum Leitpfosten",
                          HOL__NL("loop naar de paal")},
#endif
    [HOL_S_LESSON_1] = {"1/4 Step onto the marked tile ahead",
                        "1/4 Tritt auf die markierte Kachel vor dir",
                        HOL__NL("1/4 Stap op de gemarkeerde tegel voor je")},
    [HOL_S_LESSON_2] = {"2/4 Walk round the marked tree to this cell",
                        "2/4 Um den markierten Baum in diese Zelle",
                        HOL__NL("2/4 Loop om de gemarkeerde boom naar deze cel")},
    [HOL_S_LESSON_3] = {"3/4 Use the map: reach the marker",
                        "3/4 Nutze die Karte: zur Markierung",
                        HOL__NL("3/4 Gebruik de kaart: naar de marker")},
    [HOL_S_LESSON_4] = {"4/4 Find the flag, every cue on",
                        "4/4 Finde die Fahne, alle Hilfen an",
                        HOL__NL("4/4 Vind de vlag, alle hulp aan")},
    [HOL_S_LESSON_3_NOMAP] = {"3/4 Reach the marker",
                              "3/4 Geh zur Markierung",
                              HOL__NL("3/4 Loop naar de marker")},
    [HOL_S_ROUTE_FMT] = {"Follow the markers %d/%d",
                         "Folge den Markierungen %d/%d",
                         HOL__NL("Volg de markers %d/%d")},
    [HOL_S_LESSON_1_DONE] = {"Well done: one step, one new tile",
                             "Gut: ein Schritt, eine neue Kachel",
                             HOL__NL("Goed: één stap, één nieuwe tegel")},
    [HOL_S_LESSON_2_DONE] = {"Same cell, another tile: that is holonomy",
                             "Dieselbe Zelle, andere Kachel: Holonomie",
                             HOL__NL("Zelfde cel, andere tegel: dat is holonomie")},
    [HOL_S_LESSON_3_DONE] = {"Found it: the map knows the way",
                             "Gefunden: die Karte kennt den Weg",
                             HOL__NL("Gevonden: de kaart kent de weg")},
    [HOL_S_LESSON_4_DONE] = {"Flag found: you can play",
                             "Fahne gefunden: du kannst spielen",
                             HOL__NL("Vlag gevonden: je kunt spelen")},
    [HOL_S_PATH] = {"Map line: the fewest steps to the marker",
                    "Kartenlinie: der kürzeste Weg zur Markierung",
                    HOL__NL("Lijn op de kaart: de kortste weg naar de marker")},
    [HOL_S_RINGS] = {"Rings on the map: the two tiles of this cell",
                     "Ringe: die zwei Kacheln dieser Zelle",
                     HOL__NL("Ringen: de twee tegels van deze cel")},
    [HOL_S_FIXED] = {"Minimap fixed in this study",
                     "Karte in dieser Studie fest",
                     HOL__NL("Kaart staat vast in dit onderzoek")},
    [HOL_S_PAUSED] = {"Paused",
                      "Pause",
                      HOL__NL("Pauze")},
    [HOL_S_POINT_CTRL_START] = {"Point the controller at the start",
                                "Zeig mit dem Controller auf den Start",
                                HOL__NL("Wijs met de controller naar de start")},
    [HOL_S_POINT_CTRL_CHEST] = {"Point the controller at the chest",
                                "Zeig mit dem Controller auf die Truhe",
                                HOL__NL("Wijs met de controller naar de kist")},
    [HOL_S_POINT_CTRL_FLAG] = {"Point the controller at the flag",
                               "Zeig mit dem Controller auf die Fahne",
                               HOL__NL("Wijs met de controller naar de vlag")},
    [HOL_S_POINT_FACE_START] = {"Turn to face the start",
                                "Dreh dich zum Start",
                                HOL__NL("Draai je naar de start")},
    [HOL_S_POINT_FACE_CHEST] = {"Turn to face the chest",
                                "Dreh dich zur Truhe",
                                HOL__NL("Draai je naar de kist")},
    [HOL_S_POINT_FACE_FLAG] = {"Turn to face the flag",
                               "Dreh dich zur Fahne",
                               HOL__NL("Draai je naar de vlag")},
    [HOL_S_TIME_UP_FMT] = {"Time up: %d steps, best %d, %ld:%02ld",
                           "Zeit um: %d Schritte, Minimum %d, %ld:%02ld",
                           HOL__NL("Tijd op: %d stappen, best %d, %ld:%02ld")},
    [HOL_S_TUTORIAL_DONE_FMT] = {"Tutorial done: %d steps, %ld:%02ld",
                                 "Einführung fertig: %d Schritte, %ld:%02ld",
                                 HOL__NL("Uitleg klaar: %d stappen, %ld:%02ld")},
    [HOL_S_DONE_FMT] = {"Done: %d steps, best %d, %ld:%02ld",
                        "Fertig: %d Schritte, Minimum %d, %ld:%02ld",
                        HOL__NL("Klaar: %d stappen, best %d, %ld:%02ld")},
    [HOL_S_DEVICE_LOST] = {"Controller lost",
                           "Controller getrennt",
                           HOL__NL("Controller kwijt")},
    [HOL_S_OUTSIDE] = {"Outside the room: step back in",
                       "Außerhalb des Raums: tritt zurück",
                       HOL__NL("Buiten de kamer: stap terug")},
    [HOL_S_READY] = {"Ready? The clock starts when you begin.",
                     "Bereit? Die Uhr läuft, sobald du losgehst.",
                     HOL__NL("Klaar? De klok loopt zodra je begint.")},
    [HOL_S_DEVICE_BACK] = {"Plug it back in, or press a key",
                           "Wieder anstecken oder eine Taste drücken",
                           HOL__NL("Sluit hem weer aan, of druk op een toets")},
    [HOL_S_SMALL_AREA_FMT] = {"Play area under %.12s m: mind the edges",
                              "Spielfläche unter %.12s m: Vorsicht am Rand",
                              HOL__NL("Speelruimte onder %.12s m: let op de randen")},
    [HOL_S_MOVE_KEYBOARD] = {"W/S/A/D: WALK, ARROWS: TURN",
                             "W/S/A/D: GEHEN, PFEILE: DREHEN",
                             HOL__NL("W/S/A/D: LOPEN, PIJLEN: DRAAIEN")},
    [HOL_S_MOVE_GAMEPAD] = {"LEFT STICK: WALK, RIGHT STICK: TURN",
                            "LINKER STICK: GEHEN, RECHTER: DREHEN",
                            HOL__NL("LINKER STICK: LOPEN, RECHTER: DRAAIEN")},
    [HOL_S_MOVE_ROOM] = {"WALK IN YOUR ROOM",
                         "GEH IN DEINEM RAUM",
                         HOL__NL("LOOP IN JE KAMER")},
    [HOL_S_DO_FINISH] = {"finish",
                         "beenden",
                         HOL__NL("afsluiten")},
    [HOL_S_DO_BEGIN] = {"begin",
                        "anfangen",
                        HOL__NL("beginnen")},
    [HOL_S_DO_QUIT] = {"quit",
                       "aufhören",
                       HOL__NL("stoppen")},
    [HOL_S_DO_CONFIRM] = {"confirm",
                          "bestätigen",
                          HOL__NL("bevestigen")},
    [HOL_S_DO_RESUME] = {"resume",
                         "weiter",
                         HOL__NL("verder")},
    [HOL_S_DO_RESTART] = {"restart",
                          "von vorn",
                          HOL__NL("opnieuw")},
    [HOL_S_DO_ANSWER] = {"answer",
                         "antworten",
                         HOL__NL("antwoorden")},
    [HOL_S_DO_NEXT_LEVEL] = {"next level",
                             "nächstes Level",
                             HOL__NL("volgend level")},
    [HOL_S_DO_AGAIN] = {"again",
                        "nochmal",
                        HOL__NL("nog eens")},
    [HOL_S_DO_MENU] = {"menu",
                       "Menü",
                       HOL__NL("menu")},
    [HOL_S_DO_MAP] = {"map on the HUD, in the hand, off",
                      "Karte im HUD, in der Hand, aus",
                      HOL__NL("kaart in de HUD, in de hand, uit")},
    [HOL_S_STEPS_FMT] = {"STEPS %d",
                         "SCHRITTE %d",
                         HOL__NL("STAPPEN %d")},
    [HOL_S_TIME_OF_FMT] = {"TIME %ld:%02ld OF %ld:%02ld",
                           "ZEIT %ld:%02ld VON %ld:%02ld",
                           HOL__NL("TIJD %ld:%02ld VAN %ld:%02ld")},
    [HOL_S_TIME_FMT] = {"TIME %ld:%02ld",
                        "ZEIT %ld:%02ld",
                        HOL__NL("TIJD %ld:%02ld")},
    [HOL_S_TILE_FMT] = {"TILE %.40s",
                        "KACHEL %.40s",
                        HOL__NL("TEGEL %.40s")},
    [HOL_S_CELL_FMT] = {"CELL %d,%d NORTH %d",
                        "ZELLE %d,%d NORD %d",
                        HOL__NL("CEL %d,%d NOORD %d")},
    [HOL_S_CAP_START] = {"[Sound: chime, the level begins]",
                         "[Ton: Glocke, das Level beginnt]",
                         HOL__NL("[Geluid: bel, het level begint]")},
    [HOL_S_CAP_KEY] = {"[Sound: chime, a key collected]",
                       "[Ton: Glocke, ein Schlüssel gefunden]",
                       HOL__NL("[Geluid: bel, een sleutel gevonden]")},
    [HOL_S_CAP_CHEST] = {"[Sound: chime, the chest opens]",
                         "[Ton: Glocke, die Truhe geht auf]",
                         HOL__NL("[Geluid: bel, de kist gaat open]")},
    [HOL_S_CAP_FLAG] = {"[Sound: chime, the flag reached]",
                        "[Ton: Glocke, die Fahne erreicht]",
                        HOL__NL("[Geluid: bel, de vlag bereikt]")},
    [HOL_S_CAP_BEACON] = {"[Sound: beacons pip at the goals]",
                          "[Ton: Signale piepen an den Zielen]",
                          HOL__NL("[Geluid: bakens piepen bij de doelen]")},
    [HOL_S_PAUSE_UNFOCUSED] = {"the window is not focused",
                               "das Fenster ist nicht im Fokus",
                               HOL__NL("het venster heeft geen focus")},
    [HOL_S_PAUSE_HEADSET_OFF] = {"the headset is off",
                                 "die Brille ist abgesetzt",
                                 HOL__NL("de bril is af")},
    [HOL_S_PAUSE_SYSTEM_MENU] = {"a system menu is over the game",
                                 "ein Systemmenü ist offen",
                                 HOL__NL("een systeemmenu ligt over het spel")},
    [HOL_S_PAUSE_PAD_GONE] = {"the game controller went away",
                              "der Controller ist weg",
                              HOL__NL("de controller is weg")},
    [HOL_S_PAUSE_MENU] = {"the menu is open",
                          "das Menü ist offen",
                          HOL__NL("het menu is open")},
    [HOL_S_FIT_FMT] = {"Room %d x %d cells of %s m fits your %s x %s m play area",
                       "Raum %d x %d Zellen zu %s m passt in deine %s x %s m Spielfläche",
                       HOL__NL("Kamer van %d x %d cellen van %s m past in je speelruimte van %s x %s m")},
    [HOL_S_FIT_SMALL_FMT] = {"Your %s x %s m play area is smaller than the smallest room (3 x 3 cells of 0.5 m and %s m clear): playing 3 x 3 cells of 0.5 m, keep to the middle",
                             "Deine %s x %s m Spielfläche ist zu klein für 3 x 3 Zellen zu 0.5 m und %s m Rand: bleib in der Mitte",
                             HOL__NL("Je speelruimte van %s x %s m is kleiner dan de kleinste kamer (3 x 3 cellen van 0.5 m en %s m vrij): je speelt 3 x 3 cellen van 0.5 m, blijf in het midden")},
#ifndef HOL_STR_NO_PAGE /* the web build: its text.js carries the page's words */
    [HOL_S_PAGE_LOADING] = {"Loading…",
                            "Lädt…",
                            HOL__NL("Laden…")},
    [HOL_S_PAGE_OK] = {"OK",
                       "OK",
                       HOL__NL("OK")},
    [HOL_S_PAGE_BACK] = {"Back",
                         "Zurück",
                         HOL__NL("Terug")},
    [HOL_S_PAGE_MENU] = {"Menu",
                         "Menü",
                         HOL__NL("Menu")},
    [HOL_S_PAGE_MAP] = {"Map",
                        "Karte",
                        HOL__NL("Kaart")},
    [HOL_S_PAGE_VR_ENTER] = {"Enter VR",
                             "VR starten",
                             HOL__NL("VR starten")},
    [HOL_S_PAGE_VR_EXIT] = {"Exit VR",
                            "VR beenden",
                            HOL__NL("VR verlaten")},
    [HOL_S_PAGE_VR_HTTPS] = {"VR needs https:// or localhost",
                             "VR braucht https:// oder localhost",
                             HOL__NL("VR heeft https:// of localhost nodig")},
    [HOL_S_PAGE_VR_HTTPS_WHY] = {"WebXR runs only on a secure page: open it with https://, or from localhost (docs/web.md)",
                                 "WebXR läuft nur auf einer sicheren Seite: öffne sie mit https:// oder von localhost (docs/web.md)",
                                 HOL__NL("WebXR werkt alleen op een veilige pagina: open hem met https://, of vanaf localhost (docs/web.md)")},
    [HOL_S_PAGE_VR_NONE] = {"No VR in this browser",
                            "Kein VR in diesem Browser",
                            HOL__NL("Geen VR in deze browser")},
    [HOL_S_PAGE_VR_NONE_WHY] = {"this browser has no WebXR",
                                "dieser Browser hat kein WebXR",
                                HOL__NL("deze browser heeft geen WebXR")},
    [HOL_S_PAGE_VR_NO_HEADSET] = {"No VR headset found",
                                  "Keine VR-Brille gefunden",
                                  HOL__NL("Geen VR-bril gevonden")},
    [HOL_S_PAGE_VR_NO_HEADSET_WHY] = {"connect a headset (or open the page in its browser) and reload",
                                      "schließe eine Brille an (oder öffne die Seite in ihrem Browser) und lade neu",
                                      HOL__NL("sluit een bril aan (of open de pagina in zijn browser) en laad opnieuw")},
    [HOL_S_PAGE_AGAIN] = {"Play again",
                          "Nochmal spielen",
                          HOL__NL("Nog eens spelen")},
    [HOL_S_PAGE_FIT] = {"Play the room that fits your play area",
                        "Den Raum spielen, der in deine Spielfläche passt",
                        HOL__NL("Speel de kamer die in je speelruimte past")},
    [HOL_S_PAGE_FILE] = {"Level file…",
                         "Level-Datei…",
                         HOL__NL("Levelbestand…")},
    [HOL_S_PAGE_FILE_WHY] = {"Play a level file (SPEC section 5)",
                             "Eine Level-Datei spielen (SPEC Abschnitt 5)",
                             HOL__NL("Een levelbestand spelen (SPEC paragraaf 5)")},
    [HOL_S_PAGE_LOGS] = {"Logs",
                         "Protokolle",
                         HOL__NL("Logs")},
    [HOL_S_PAGE_HELP] = {"Click the view to look with the mouse · W/S/A/D walk · arrows turn · P menu · M map · R restart · Enter next · F2 frame time · Q quit",
                         "Klick ins Bild, um mit der Maus zu schauen · W/S/A/D gehen · Pfeile drehen · P Menü · M Karte · R neu starten · Enter weiter · F2 Bildzeit · Q beenden",
                         HOL__NL("Klik in het beeld om met de muis te kijken · W/S/A/D lopen · pijlen draaien · P menu · M kaart · R opnieuw · Enter verder · F2 beeldtijd · Q stoppen")},
    [HOL_S_PAGE_NO_LOGS] = {"No logs yet.",
                            "Noch keine Protokolle.",
                            HOL__NL("Nog geen logs.")},
    [HOL_S_PAGE_CLEAR] = {"Delete all logs",
                          "Alle Protokolle löschen",
                          HOL__NL("Alle logs wissen")},
    [HOL_S_PAGE_CLEAR_ASK] = {"Delete every log and recording kept in this browser?",
                              "Alle Protokolle und Aufnahmen in diesem Browser löschen?",
                              HOL__NL("Alle logs en opnamen in deze browser wissen?")},
    [HOL_S_PAGE_BYTES] = {"bytes",
                          "Bytes",
                          HOL__NL("bytes")},
    [HOL_S_PAGE_PLAYING] = {"Playing",
                            "Im Spiel",
                            HOL__NL("Aan het spelen")},
    [HOL_S_PAGE_PLAYING_LEVEL] = {"Playing %s",
                                  "Im Spiel: %s",
                                  HOL__NL("Aan het spelen: %s")},
    [HOL_S_PAGE_IN_VR] = {"In VR",
                          "In VR",
                          HOL__NL("In VR")},
    [HOL_S_PAGE_PAUSED] = {"Paused: %s",
                           "Pause: %s",
                           HOL__NL("Pauze: %s")},
    [HOL_S_PAGE_OVER] = {"Session over: the logs are kept in this browser (Logs).",
                         "Sitzung beendet: die Protokolle bleiben in diesem Browser (Protokolle).",
                         HOL__NL("Sessie voorbij: de logs blijven in deze browser (Logs).")},
    [HOL_S_PAGE_FAILED] = {"Failed: %s",
                           "Fehler: %s",
                           HOL__NL("Mislukt: %s")},
    [HOL_S_PAGE_WARNING] = {"Warning: %s",
                            "Warnung: %s",
                            HOL__NL("Waarschuwing: %s")},
    [HOL_S_PAGE_VR_FAILED] = {"VR failed: %s",
                              "VR fehlgeschlagen: %s",
                              HOL__NL("VR mislukt: %s")},
    [HOL_S_PAGE_NO_STUDY] = {"Cannot load the study: %s",
                             "Die Studie lädt nicht: %s",
                             HOL__NL("Het onderzoek laadt niet: %s")},
    [HOL_S_PAGE_NO_LEVEL] = {"Cannot load the level: %s",
                             "Das Level lädt nicht: %s",
                             HOL__NL("Het level laadt niet: %s")},
    [HOL_S_PAGE_NO_GAME] = {"cannot load the game",
                            "das Spiel lädt nicht",
                            HOL__NL("het spel laadt niet")},
    [HOL_S_PAGE_NO_START] = {"cannot start the game",
                             "das Spiel startet nicht",
                             HOL__NL("het spel start niet")},
#endif
};

static const char hol__code[HOL_LANG_COUNT][3] = {"en", "de", "nl"};

/* 1: this build holds the language. */
static int hol__held(int lang)
{
    return lang >= 0 && lang < HOL_LANG_COUNT && hol__rows[HOL_S_OBJ_FLAG][lang];
}

const char *hol_str(int lang, hol_str_id id)
{
    if (!hol__held(lang))
        lang = HOL_LANG_EN; /* and a language this build leaves out */
    if ((int)id < 0 || id >= HOL__NSTR)
        return "";
    const char *s = hol__rows[id][lang];
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
        if (hol__held(l) && hol__lower(tag[0]) == hol__code[l][0] && tag[0] &&
            hol__lower(tag[1]) == hol__code[l][1] && tag[1] &&
            (tag[2] == 0 || tag[2] == '-' || tag[2] == '_'))
            return l;
    return -1;
}

const char *hol_lang_code(int lang)
{
    return hol__code[lang >= 0 && lang < HOL_LANG_COUNT ? lang : HOL_LANG_EN];
}
