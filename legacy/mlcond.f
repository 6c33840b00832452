C=======================================================================
C     MLCOND - THE CONDUCTORS, CIRCLES AND ARCS OF THE CONDUCTOR TAPE
C                                                              (M703L)
C     SOURCE:  REPORT (THE CONDUCTOR TAPE, M703L); DOCS/CARDS.MD. EACH
C              CONDUCTOR (AN L CARD AND ITS + CARDS), CIRCLE (O) AND
C              ARC (A) IS ONE ITEM OF THE TOUR.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE MLCOND
      IMPLICIT NONE
C     ---- /TZGEO/ THE BOARD: PADS, CONDUCTORS, CIRCLES AND ARCS -------
      INTEGER MXPAD, MXCON, MXVTX, MXARC
      PARAMETER (MXPAD = 200000, MXCON = 50000, MXVTX = 200000,
     1           MXARC = 50000)
      INTEGER NPAD, KPX(MXPAD), KPY(MXPAD), KPW(MXPAD), KPH(MXPAD),
     1        KPN(MXPAD), KPSX(MXPAD), KPSY(MXPAD), KPCRD(MXPAD),
     2        NCON, KCV1(MXCON), KCV2(MXCON), KCW(MXCON), KCCRD(MXCON),
     3        NVTX, KVX(MXVTX), KVY(MXVTX), KVCRD(MXVTX),
     4        NARC, KAX(MXARC), KAY(MXARC), KADX(MXARC), KADY(MXARC),
     5        KAXS(MXARC), KAYS(MXARC), KAK(MXARC), KACRD(MXARC),
     6        LCOPEN, LGFULL
      COMMON /TZGEO/ NPAD, KPX, KPY, KPW, KPH, KPN, KPSX, KPSY, KPCRD,
     1               NCON, KCV1, KCV2, KCW, KCCRD, NVTX, KVX, KVY,
     2               KVCRD, NARC, KAX, KAY, KADX, KADY, KAXS, KAYS,
     3               KAK, KACRD, LCOPEN, LGFULL
      SAVE /TZGEO/
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM), NJOB
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI, NJOB
      SAVE /CMITM/
C     ---- LOCAL -------------------------------------------------------
      EXTERNAL MLITEM
      INTEGER I
C
C     THE ITEMS OF ALL THE PACKAGE'S TAPES: ON A BIG BOARD EVEN A SMALL
C     TAPE GETS FEWER KICKS (CMTOUR)
      NJOB = NPAD + NCON + NARC
      NITM = 0
      DO 10 I = 1, NCON
         NITM = NITM + 1
         IKND(NITM) = 3
         IREF(NITM) = I
   10 CONTINUE
      DO 20 I = 1, NARC
         NITM = NITM + 1
         IKND(NITM) = 4
         IREF(NITM) = I
   20 CONTINUE
      CALL CMASSM(MLITEM)
      RETURN
C     END OF MLCOND
      END
