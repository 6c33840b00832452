/*
 * The device seam of the f2c build of TENZOR (scripts/judges.sh f2c).
 *
 * The FORTRAN 77 of legacy/ calls eight device routines, DVCARD ... DVCLOS,
 * which src/monitor/devices.f90 supplies (the monitor's card reader, printer,
 * punches and console). Translated by f2c, legacy/ passes the length of a
 * CHARACTER argument as an f2c "ftnlen" (a 32-bit int, f2c.h); gfortran's
 * routines expect it as a size_t (the gfortran manual, "Argument passing
 * conventions"). So the f2c translation is compiled with each name dvxxxx_
 * renamed f2c_dvxxxx_ (scripts/judges.sh), and the routines here take the f2c
 * convention and call the monitor's with the gfortran one. They do nothing
 * else: the f2c build and the gfortran build share every line of the monitor.
 */
#include <stddef.h>
#include "f2c.h"

/* src/monitor/devices.f90, as gfortran compiles it */
extern void dvcard_(char *card, integer *ncol, integer *iend, size_t card_len);
extern void dvprnt_(char *line, size_t line_len);
extern void dverr_(char *line, size_t line_len);
extern void dvopen_(char *name, size_t name_len);
extern void dvpnch_(integer *iu, integer *irow);
extern void dvtext_(integer *iu, char *line, size_t line_len);
extern void dvjob_(char *line, size_t line_len);
extern void dvclos_(integer *ikeep);

/* a length as f2c passes it: never negative (f2c computes 0 at least) */
static size_t len_of(ftnlen n) { return n > 0 ? (size_t)n : 0; }

int f2c_dvcard_(char *card, integer *ncol, integer *iend, ftnlen card_len)
{
    dvcard_(card, ncol, iend, len_of(card_len));
    return 0;
}

int f2c_dvprnt_(char *line, ftnlen line_len)
{
    dvprnt_(line, len_of(line_len));
    return 0;
}

int f2c_dverr_(char *line, ftnlen line_len)
{
    dverr_(line, len_of(line_len));
    return 0;
}

int f2c_dvopen_(char *name, ftnlen name_len)
{
    dvopen_(name, len_of(name_len));
    return 0;
}

int f2c_dvpnch_(integer *iu, integer *irow)
{
    dvpnch_(iu, irow);
    return 0;
}

int f2c_dvtext_(integer *iu, char *line, ftnlen line_len)
{
    dvtext_(iu, line, len_of(line_len));
    return 0;
}

int f2c_dvjob_(char *line, ftnlen line_len)
{
    dvjob_(line, len_of(line_len));
    return 0;
}

int f2c_dvclos_(integer *ikeep)
{
    dvclos_(ikeep);
    return 0;
}
