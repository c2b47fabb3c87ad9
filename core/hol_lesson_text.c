/* hol_lesson_text.c - every text a lesson shows, as one table in every
 * language (see hol_lesson.h; the rows as core/hol_str.c's: one entry, its
 * English, German and Dutch side by side), and its expansion with the
 * lesson's facts.
 *
 * A text names facts as {name}; every number comes from the core
 * (hol_lesson_facts), none is typed here: {q} squares at a corner, {deg} a
 * corner's degrees, {sum} a square's four, {end} the route's last tile,
 * {home} its fewest steps home, {flat} the flat grid's steps home (the
 * cells), {bearing} where the start lies from the end ("at B degrees",
 * or "under you"), {dir} lesson 3's right choice, {yesno} lesson 1's,
 * {close} "close" in {4,4} and "do not close" else, {steps} the route's
 * steps, {c1} {c2} {c3} the tiles at 1, 2, 3 steps here, {f1}.. in {4,4},
 * {h1}.. in {4,5}, {times} the squares walked until home and {walked}
 * their steps. A language's text names the English one's facts
 * (tests/test_str.c). Kept short: the web page carries them (docs/web.md,
 * the transfer size). German and Dutch name the directions as their
 * compasses do (N, O, S, W; N, O, Z, W): the route is the same. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_lesson.h"
#include "hol_str.h"

/* The worksheet's texts (title, goal, and the hints but lesson 6's, which
 * the app shows on request): left out of a build that defines
 * HOL_LESSON_APP_ONLY (the web page: its transfer size), where the app
 * shows none of them. */
#ifdef HOL_LESSON_APP_ONLY
#define HOL__SHEET(s) ""
#else
#define HOL__SHEET(s) s
#endif
/* A build without Dutch (the web's, as core/hol_str.c's) reads English. */
#define HOL__NL(s) HOL_STR_NL(s)
#define HOL__ROW(en, de, nl) {en, de, HOL__NL(nl)}
#define HOL__SROW(en, de, nl) {HOL__SHEET(en), HOL__SHEET(de), HOL__NL(HOL__SHEET(nl))}

#define HOL__COLS (HOL_LESSON_PARTS + HOL_APP_MAX_CHOICES)

/* Per lesson: title, goal, question, walk, check, hint (the columns of
 * enum hol_lesson_part), then the choices or the scale's two anchors. */
static const char *const hol__lessons[HOL_LESSONS][HOL__COLS][HOL_LANG_COUNT] = {
    {HOL__SROW("One step, one tile", "Ein Schritt, eine Kachel", "Eén stap, één tegel"),
     HOL__SROW("A square walk N, E, S, W closes on paper, not in the hyperbolic plane.",
               "Ein Quadratweg N, O, S, W schließt sich auf Papier, nicht in der "
               "hyperbolischen Ebene.",
               "Een vierkante wandeling N, O, Z, W sluit op papier, niet in het hyperbolische "
               "vlak."),
     HOL__ROW("Walk N, E, S, W. Are you back on your start tile?",
              "Geh N, O, S, W. Stehst du wieder auf deiner Startkachel?",
              "Loop N, O, Z, W. Sta je weer op je starttegel?"),
     HOL__ROW("Walk N, E, S, W: step onto each marker and watch where you end.",
              "Geh N, O, S, W: tritt auf jede Markierung und schau, wo du ankommst.",
              "Loop N, O, Z, W: stap op elke marker en kijk waar je uitkomt."),
     HOL__ROW("Answer: {yesno}. You ended on tile {end}, {home} step(s) from the start O: {q} "
              "squares meet at each corner, so four right turns {close} a square.",
              "Antwort: {yesno}. Du stehst auf Kachel {end}, {home} Schritt(e) vom Start O: an "
              "jeder Ecke treffen sich {q} Quadrate, also {close}.",
              "Antwoord: {yesno}. Je staat op tegel {end}, {home} stap(pen) van de start O: bij "
              "elke hoek komen {q} vierkanten samen, dus {close}."),
     HOL__SROW("Count the squares that meet at one corner of your cell.",
               "Zähl die Quadrate, die sich an einer Ecke deiner Zelle treffen.",
               "Tel de vierkanten die samenkomen in één hoek van je cel."),
     HOL__ROW("Yes", "Ja", "Ja"), HOL__ROW("No", "Nein", "Nee")},
    {HOL__SROW("Corners", "Ecken", "Hoeken"),
     HOL__SROW("{q} squares meet at a corner: a corner is {deg} degrees, a square's four "
               "sum to {sum}.",
               "An einer Ecke treffen sich {q} Quadrate: eine Ecke hat {deg} Grad, die vier "
               "eines Quadrats zusammen {sum}.",
               "Bij een hoek komen {q} vierkanten samen: een hoek is {deg} graden, de vier van "
               "een vierkant samen {sum}."),
     HOL__ROW("How many squares meet at a corner (round one tree)?",
              "Wie viele Quadrate treffen sich an einer Ecke (um einen Baum)?",
              "Hoeveel vierkanten komen samen bij een hoek (rond één boom)?"),
     HOL__ROW("Walk round the tree at your cell's north-west corner, following the markers, "
              "back to your start tile. Count the tiles.",
              "Geh um den Baum an der Nordwestecke deiner Zelle, den Markierungen nach, zurück "
              "auf deine Startkachel. Zähl die Kacheln.",
              "Loop om de boom op de noordwesthoek van je cel, volg de markers, terug naar je "
              "starttegel. Tel de tegels."),
     HOL__ROW("Answer: {q}. So a square's corner is 360/{q} = {deg} degrees, and its four "
              "corners sum to {sum} (360 on paper).",
              "Antwort: {q}. Eine Ecke eines Quadrats hat also 360/{q} = {deg} Grad, und seine "
              "vier Ecken zusammen {sum} (auf Papier 360).",
              "Antwoord: {q}. Een hoek van een vierkant is dus 360/{q} = {deg} graden, en zijn "
              "vier hoeken samen {sum} (op papier 360)."),
     HOL__SROW("The walk ends on the tile where it began: count its steps.",
               "Der Weg endet auf der Kachel, wo er begann: zähl seine Schritte.",
               "De wandeling eindigt op de tegel waar hij begon: tel de stappen."),
     HOL__ROW("fewer", "weniger", "minder"), HOL__ROW("more", "mehr", "meer")},
    {HOL__SROW("Holonomy", "Holonomie", "Holonomie"),
     HOL__SROW("A walk round one tree brings you back to your cell but onto another tile "
               "(holonomy).",
               "Ein Weg um einen Baum bringt dich zurück in deine Zelle, aber auf eine andere "
               "Kachel (Holonomie).",
               "Een wandeling rond één boom brengt je terug in je cel, maar op een andere tegel "
               "(holonomie)."),
     HOL__ROW("You walk N, W, S, E round a tree, back to your cell. Where is the start tile?",
              "Du gehst N, W, S, O um einen Baum, zurück in deine Zelle. Wo ist die "
              "Startkachel?",
              "Je loopt N, W, Z, O rond een boom, terug naar je cel. Waar is de starttegel?"),
     HOL__ROW("Walk N, W, S, E round the tree, following the markers, then point to the start "
              "tile.",
              "Geh N, W, S, O um den Baum, den Markierungen nach, und zeig dann auf die "
              "Startkachel.",
              "Loop N, W, Z, O rond de boom, volg de markers, en wijs dan naar de starttegel."),
     HOL__ROW("Answer: {dir}. Back in your cell, you are on tile {end}: {q} squares stand round "
              "the tree and you passed {steps}, so the start lies {bearing}.",
              "Antwort: {dir}. Zurück in deiner Zelle stehst du auf Kachel {end}: {q} Quadrate "
              "stehen um den Baum und du bist an {steps} vorbei, also liegt der Start "
              "{bearing}.",
              "Antwoord: {dir}. Terug in je cel sta je op tegel {end}: er staan {q} vierkanten "
              "rond de boom en je liep langs {steps}, dus de start ligt {bearing}."),
     HOL__SROW("A tree has {q} squares round it, and you walk past four.",
               "Um einen Baum stehen {q} Quadrate, und du gehst an vier vorbei.",
               "Rond een boom staan {q} vierkanten, en je loopt langs vier."),
     HOL__ROW("Under my feet", "Unter meinen Füßen", "Onder mijn voeten"),
     HOL__ROW("North", "Norden", "Noord"), HOL__ROW("East", "Osten", "Oost"),
     HOL__ROW("South", "Süden", "Zuid"), HOL__ROW("West", "Westen", "West")},
    {HOL__SROW("Growth", "Wachstum", "Groei"),
     HOL__SROW("Tiles at 1, 2, 3 steps: {c1}, {c2}, {c3}; on a flat grid {f1}, {f2}, {f3}.",
               "Kacheln in 1, 2, 3 Schritten: {c1}, {c2}, {c3}; im flachen Gitter {f1}, {f2}, "
               "{f3}.",
               "Tegels op 1, 2, 3 stappen: {c1}, {c2}, {c3}; in een plat rooster {f1}, {f2}, "
               "{f3}."),
     HOL__ROW("How many tiles lie exactly 3 steps from the start tile?",
              "Wie viele Kacheln liegen genau 3 Schritte von der Startkachel entfernt?",
              "Hoeveel tegels liggen precies 3 stappen van de starttegel?"),
     HOL__ROW("Walk the ring of cells round your start, following the markers.",
              "Geh den Ring der Zellen um deinen Start ab, den Markierungen nach.",
              "Loop de ring van cellen rond je start, volg de markers."),
     HOL__ROW("Answer: {c3}. At 1, 2, 3 steps lie {c1}, {c2}, {c3} tiles; on a flat grid {f1}, "
              "{f2}, {f3}; in {4,5} {h1}, {h2}, {h3}.",
              "Antwort: {c3}. In 1, 2, 3 Schritten liegen {c1}, {c2}, {c3} Kacheln; im flachen "
              "Gitter {f1}, {f2}, {f3}; in {4,5} {h1}, {h2}, {h3}.",
              "Antwoord: {c3}. Op 1, 2, 3 stappen liggen {c1}, {c2}, {c3} tegels; in een plat "
              "rooster {f1}, {f2}, {f3}; in {4,5} {h1}, {h2}, {h3}."),
     HOL__SROW("On a flat grid there are {f3}; here each tile has more neighbours.",
               "Im flachen Gitter sind es {f3}; hier hat jede Kachel mehr Nachbarn.",
               "In een plat rooster zijn het er {f3}; hier heeft elke tegel meer buren."),
     HOL__ROW("fewer", "weniger", "minder"), HOL__ROW("more", "mehr", "meer")},
    {HOL__SROW("No way back", "Kein Weg zurück", "Geen weg terug"),
     HOL__SROW("The fewest steps home are not what a flat map says: {home}, not {flat}.",
               "Der kürzeste Weg nach Hause ist nicht, was eine flache Karte sagt: {home}, "
               "nicht {flat}.",
               "De kortste weg naar huis is niet wat een platte kaart zegt: {home}, niet "
               "{flat}."),
     HOL__ROW("After N, E, S, W, S, W, N, N, how few steps take you to the start tile?",
              "Nach N, O, S, W, S, W, N, N: in wie wenigen Schritten bist du an der "
              "Startkachel?",
              "Na N, O, Z, W, Z, W, N, N: in hoe weinig stappen ben je bij de starttegel?"),
     HOL__ROW("Walk N, E, S, W, S, W, N, N, following the markers. Then think how you would "
              "walk home.",
              "Geh N, O, S, W, S, W, N, N, den Markierungen nach. Dann überleg, wie du nach "
              "Hause gehen würdest.",
              "Loop N, O, Z, W, Z, W, N, N, volg de markers. Denk dan na hoe je naar huis zou "
              "lopen."),
     HOL__ROW("Answer: {home}. You stand {flat} cells from your start cell but {home} steps "
              "from the start tile (you are on {end}).",
              "Antwort: {home}. Du stehst {flat} Zellen von deiner Startzelle, aber {home} "
              "Schritte von der Startkachel (du bist auf {end}).",
              "Antwoord: {home}. Je staat {flat} cellen van je startcel maar {home} stappen van "
              "de starttegel (je staat op {end})."),
     HOL__SROW("Count the tiles on the picture, not the cells.",
               "Zähl die Kacheln auf dem Bild, nicht die Zellen.",
               "Tel de tegels op het plaatje, niet de cellen."),
     HOL__ROW("fewer", "weniger", "minder"), HOL__ROW("more", "mehr", "meer")},
    {HOL__SROW("Puzzle: the square walk", "Rätsel: der Quadratweg",
               "Puzzel: de vierkante wandeling"),
     HOL__SROW("A square walk goes round one tree of {q} squares: home after {times}.",
               "Ein Quadratweg geht um einen Baum mit {q} Quadraten: zu Hause nach {times}.",
               "Een vierkante wandeling gaat rond één boom van {q} vierkanten: thuis na "
               "{times}."),
     HOL__ROW("How many times must you walk N, E, S, W to stand on your start tile again?",
              "Wie oft musst du N, O, S, W gehen, um wieder auf deiner Startkachel zu stehen?",
              "Hoe vaak moet je N, O, Z, W lopen om weer op je starttegel te staan?"),
     HOL__ROW("Walk N, E, S, W again and again, following the markers, until you are home.",
              "Geh immer wieder N, O, S, W, den Markierungen nach, bis du zu Hause bist.",
              "Loop steeds weer N, O, Z, W, volg de markers, tot je thuis bent."),
     HOL__ROW("Answer: {times}. Each step goes round the same tree, which has {q} squares "
              "round it: after {times} square(s), {walked} steps, you are home.",
              "Antwort: {times}. Jeder Schritt geht um denselben Baum, um den {q} Quadrate "
              "stehen: nach {times} Quadrat(en), {walked} Schritten, bist du zu Hause.",
              "Antwoord: {times}. Elke stap gaat rond dezelfde boom, met {q} vierkanten "
              "eromheen: na {times} vierkant(en), {walked} stappen, ben je thuis."),
     HOL__ROW("Every step of the square goes round the same tree.",
              "Jeder Schritt des Quadrats geht um denselben Baum.",
              "Elke stap van het vierkant gaat rond dezelfde boom."),
     HOL__ROW("fewer", "weniger", "minder"), HOL__ROW("more", "mehr", "meer")},
};

/* The words a fact is said in: the directions of lesson 3's answer, yes
 * and no, a square that closes or not, the bearing (a format of one %.0f
 * conversion) and a start under you. */
enum { HOL__W_DIR = 0, HOL__W_YES = 5, HOL__W_NO, HOL__W_CLOSE, HOL__W_OPEN, HOL__W_AT,
       HOL__W_UNDER, HOL__WORDS };
static const char *const hol__words[HOL__WORDS][HOL_LANG_COUNT] = {
    HOL__ROW("under your feet", "unter deinen Füßen", "onder je voeten"),
    HOL__ROW("north", "Norden", "noord"),
    HOL__ROW("east", "Osten", "oost"),
    HOL__ROW("south", "Süden", "zuid"),
    HOL__ROW("west", "Westen", "west"),
    HOL__ROW("yes", "ja", "ja"),
    HOL__ROW("no", "nein", "nee"),
    HOL__ROW("close", "ergeben vier Rechtsdrehungen ein Quadrat",
             "sluiten vier bochten naar rechts een vierkant"),
    HOL__ROW("do not close", "ergeben vier Rechtsdrehungen kein Quadrat",
             "sluiten vier bochten naar rechts geen vierkant"),
    HOL__ROW("at %.0f degrees", "in Richtung %.0f Grad", "op %.0f graden"),
    HOL__ROW("under you", "unter dir", "onder je"),
};

/* The facts' names, in the order hol__fact numbers them. */
static const char *const hol__names[] = {
    "q",  "deg", "sum", "home", "flat", "times", "walked", "steps", "c1",    "c2",    "c3",
    "f1", "f2",  "f3",  "h1",   "h2",   "h3",    "end",    "dir",   "yesno", "close", "bearing"};
#define HOL__NUMBERS 17 /* the names before "end" are numbers */
#define HOL__NNAMES ((int)(sizeof hol__names / sizeof hol__names[0]))

/* Entry e of lang, English where the build or the row lacks lang. */
static const char *hol__in(const char *const e[HOL_LANG_COUNT], int lang)
{
    return lang > 0 && lang < HOL_LANG_COUNT && e[lang] ? e[lang] : e[HOL_LANG_EN];
}

/* The word of fact k (HOL__NUMBERS + 1 ..) in lang into buf (64 bytes). */
static void hol__fact_word(const hol_lesson_facts *f, int lang, int k, char *buf)
{
    int w = k == HOL__NUMBERS + 1   ? HOL__W_DIR + (f->lesson == 3 ? f->answer : 0)
            : k == HOL__NUMBERS + 2 ? (f->lesson == 1 && !f->answer ? HOL__W_YES : HOL__W_NO)
            : k == HOL__NUMBERS + 3 ? (f->q == 4 ? HOL__W_CLOSE : HOL__W_OPEN)
            : f->has_bearing        ? HOL__W_AT
                                    : HOL__W_UNDER;
    if (w == HOL__W_AT) /* the table's format: one %.0f (tests/test_str.c) */
        snprintf(buf, 64, hol__in(hol__words[w], lang), f->bearing_deg);
    else
        snprintf(buf, 64, "%s", hol__in(hol__words[w], lang));
}

/* The fact named by name (n bytes) as text into buf (at least 64 bytes):
 * 0, or -1 for no such fact. */
static int hol__fact(const hol_lesson_facts *f, int lang, const char *name, size_t n, char *buf)
{
    int k = 0;
    while (k < HOL__NNAMES && !(strlen(hol__names[k]) == n && !memcmp(hol__names[k], name, n)))
        k++;
    double v[HOL__NUMBERS] = {f->q,       f->corner_deg, f->square_deg, f->home,
                              f->flat_home, f->repeats,  4 * f->repeats, f->nroute};
    for (int d = 1; d <= 3; d++) {
        v[7 + d] = (double)f->count[d];
        v[10 + d] = (double)f->flat_count[d];
        v[13 + d] = (double)f->curved_count[d];
    }
    if (k < HOL__NUMBERS) /* a number: whole when it is, else one decimal */
        snprintf(buf, 32, fabs(v[k] - floor(v[k] + 0.5)) < 1e-9 ? "%.0f" : "%.1f", v[k]);
    else if (k == HOL__NUMBERS)
        hol_tile_print(f->end, buf);
    else if (k < HOL__NNAMES)
        hol__fact_word(f, lang, k, buf);
    return k < HOL__NNAMES ? 0 : -1;
}

int hol_lesson_text(const hol_lesson_facts *f, int lang, int part, char *out, size_t cap)
{
    if (!f || f->lesson < 1 || f->lesson > HOL_LESSONS || part < 0 || part >= HOL_LESSON_PARTS ||
        !cap)
        return -1;
    const char *s = hol__in(hol__lessons[f->lesson - 1][part], lang);
    size_t len = 0;
    out[0] = 0;
    while (*s) {
        char fact[HOL_TILE_ADDR_MAX + 64];
        const char *piece = s, *close = *s == '{' ? strchr(s, '}') : NULL;
        size_t n = 1;
        /* "{4,5}" is no fact: only {name} of a fact is replaced */
        if (close && !hol__fact(f, lang, s + 1, (size_t)(close - s - 1), fact)) {
            piece = fact;
            n = strlen(fact);
            s = close + 1;
        } else {
            s++;
        }
        if (len + n >= cap)
            return -1;
        memcpy(out + len, piece, n);
        len += n;
        out[len] = 0;
    }
    return (int)len;
}

const char *hol_lesson_label(const hol_lesson_facts *f, int lang, int k)
{
    if (!f || f->lesson < 1 || f->lesson > HOL_LESSONS || k < 0 || k >= HOL_APP_MAX_CHOICES)
        return NULL;
    const char *const *e = hol__lessons[f->lesson - 1][HOL_LESSON_PARTS + k];
    return e[HOL_LANG_EN] ? hol__in(e, lang) : NULL;
}

const char *hol_lesson_entry(int n, int lang, int k)
{
    if (n < 1 || n > HOL_LESSONS || lang < 0 || lang >= HOL_LANG_COUNT || k < 0)
        return NULL;
    if (k < HOL__COLS)
        return hol__lessons[n - 1][k][lang];
    return k - HOL__COLS < HOL__WORDS && n == 1 ? hol__words[k - HOL__COLS][lang] : NULL;
}
