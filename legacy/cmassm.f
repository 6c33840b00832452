C=======================================================================
C     CMASSM - ORDER THE ITEMS OF A TAPE, APPEND THEIR FRAMES  (SHARED)
C     SOURCE:  RECONSTRUCTED, DOCS/RECONSTRUCTION.MD (ORDER). THE ITEMS
C              ARE ALREADY IN /CMITM/ (IKND, IREF). FOR EACH, ITS BODY
C              IS BUILT ONCE TO FIND ITS ENTRY AND EXIT POINTS; THEN THE
C              ITEMS ARE TAKEN IN DECK ORDER (P CARD 'D') OR ON A SHORT
C              TOUR (CMTOUR) FROM WHERE THE M FRAMES LEFT THE TOOL BACK
C              TO THE START POINT; EACH ITEM IS REACHED BY A MOVE WITH
C              THE TOOL RAISED (K 20) AND DRAWN FORWARD OR BACKWARD.
C              LAST, LONG MOVES ARE SPLIT TO THE P CARD'S FRAME LIMIT
C              (CMSPLT) AND RUNS OF EQUAL FRAME PAIRS ARE FOLDED INTO
C              CYCLES.
C     BODY    (INPUT)  SUBROUTINE BODY(I, IEXP, IEYP) OF THE PROGRAM
C                      THAT PUNCHES THE TAPE (MTITEM OR MLITEM):
C                      APPENDS THE FRAMES OF ITEM I, RETURNS ITS ENTRY
C                      POINT (IEXP, IEYP)
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMASSM(BODY)
      IMPLICIT NONE
      EXTERNAL BODY
C     ---- /TZPKG/ THE PACKAGE: P CARD PARAMETERS, ITS CARD IMAGES ---
      INTEGER MXCRD
      PARAMETER (MXCRD = 200000)
      INTEGER LPKG, ICFST, NPCRD, NPERR, LECHO, IPCRD, LGEOM,
     1        IX0, IY0, IWT(3), IDMAX, ISCN, ISCD, ICODE, IORD, IFMAX,
     2        NPWRN
      COMMON /TZPKG/ LPKG, ICFST, NPCRD, NPERR, LECHO, IPCRD, LGEOM,
     1               IX0, IY0, IWT, IDMAX, ISCN, ISCD, ICODE, IORD,
     2               IFMAX, NPWRN
      CHARACTER*18 PKNAME
      CHARACTER*24 PKFILE
      CHARACTER*80 CIMG(MXCRD)
      COMMON /TZPKGC/ PKNAME, PKFILE, CIMG
      SAVE /TZPKG/, /TZPKGC/
C     ---- /CMFRT/ THE FRAMES OF THE TAPE BEING PUNCHED ----------------
      INTEGER MXFRM
      PARAMETER (MXFRM = 1000000)
      INTEGER NFR, LFULL, JFX(MXFRM), JFY(MXFRM), JFDX(MXFRM),
     1        JFDY(MXFRM), JFCYC(MXFRM), JFK(MXFRM), JFCRD(MXFRM),
     2        JFCOL(MXFRM)
      COMMON /CMFRT/ NFR, LFULL, JFX, JFY, JFDX, JFDY, JFCYC, JFK,
     1               JFCRD, JFCOL
      SAVE /CMFRT/
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
      INTEGER NM, I, IP, IEX1, IEY1, IXE, IYE, ICX, ICY, I1, ICRD,
     1        ICOL, IDUM1, IDUM2, NE0
      DOUBLE PRECISION DX, DY
C
      NM = NFR
      CALL CMDISP(1, NM, DX, DY)
      ICX = NINT(MAX(MIN(DX, 1.0D9), -1.0D9))
      ICY = NINT(MAX(MIN(DY, 1.0D9), -1.0D9))
      IF (NITM .EQ. 0) RETURN
C     ---- ENTRY AND EXIT OF EVERY ITEM; AN ITEM IN ERROR (A PAD BEYOND
C     MXSTK) IS REPORTED HERE, ONCE, AND THE TAPE IS NOT BUILT FURTHER
C     ------------------------------------------------------------------
      NE0 = NPERR
      DO 10 I = 1, NITM
C        THE ENTRY POINT COMES BACK IN LOCALS: THE BODY ROUTINE ALSO
C        SEES /CMITM/, AND AN ARGUMENT IN A COMMON BLOCK THAT THE CALLEE
C        SEES MAY NOT BE DEFINED THERE (X3.9-1978 15.9.3.6)
         CALL BODY(I, IDUM1, IDUM2)
         IEX(I) = IDUM1
         IEY(I) = IDUM2
         CALL CMDISP(NM + 1, NFR, DX, DY)
         IXX(I) = IEX(I) + NINT(DX)
         IXY(I) = IEY(I) + NINT(DY)
         NFR = NM
         IF (LFULL .NE. 0) RETURN
   10 CONTINUE
      IF (NPERR .GT. NE0) RETURN
C     ---- THE ORDER ---------------------------------------------------
      IF (IORD .EQ. 2) THEN
         DO 20 I = 1, NITM
            ITOUR(I) = I
            IPOS(I) = I
            IORI(I) = 0
   20    CONTINUE
      ELSE
         CALL CMTOUR(ICX, ICY)
      END IF
C     ---- THE FRAMES --------------------------------------------------
      DO 30 IP = 1, NITM
         I = ITOUR(IP)
         IF (IORI(I) .EQ. 0) THEN
            IEX1 = IEX(I)
            IEY1 = IEY(I)
            IXE = IXX(I)
            IYE = IXY(I)
         ELSE
            IEX1 = IXX(I)
            IEY1 = IXY(I)
            IXE = IEX(I)
            IYE = IEY(I)
         END IF
         IF (IEX1 .NE. ICX .OR. IEY1 .NE. ICY) THEN
            CALL CMITCD(I, ICRD, ICOL)
            CALL CMFADD(0, 0, IEX1 - ICX, IEY1 - ICY, 0, 20, ICRD, ICOL)
         END IF
         I1 = NFR + 1
         CALL BODY(I, IDUM1, IDUM2)
C        AN ITEM THAT ENDS WHERE IT STARTS (A CIRCLE) IS ALWAYS DRAWN
C        FORWARD: A CIRCLE KEEPS THE DIRECTION OF ITS CARD
         IF (IORI(I) .EQ. 1 .AND. (IEX1 .NE. IXE .OR. IEY1 .NE. IYE))
     1      CALL CMREV(I1, NFR)
         ICX = IXE
         ICY = IYE
         IF (LFULL .NE. 0) RETURN
   30 CONTINUE
      CALL CMSPLT(NM + 1)
      CALL CMFOLD(NM + 1)
      RETURN
C     END OF CMASSM
      END
