#include "hol_err.h"

const char *hol_err_str(hol_err e)
{
    switch (e) {
    case HOL_OK: return "ok";
    case HOL_EPARSE: return "syntax error";
    case HOL_ENOTCANON: return "not a canonical address";
    case HOL_ERANGE: return "beyond the reach of tile words";
    case HOL_EROOM: return "step leaves the room";
    case HOL_EARG: return "argument out of range";
    case HOL_ENOMEM: return "fixed capacity exhausted";
    case HOL_EIO: return "input/output error";
    case HOL_ECORRUPT: return "corrupt data";
    case HOL_EVERSION: return "unsupported format version";
    case HOL_EBUDGET: return "search budget exhausted";
    case HOL_EUNSUPPORTED: return "not supported in this build";
    case HOL_EOPEN: return "cannot open the file";
    case HOL_EUNREACH: return "no walk inside the room reaches it";
    case HOL_ERR_COUNT: break;
    }
    return "unknown error";
}
