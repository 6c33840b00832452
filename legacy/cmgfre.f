C=======================================================================
C     CMGFRE - THE FREE JOIN OF AN END, IF IT HAS ONE           (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMGJN). AN END OF A UNIT WHOSE TWO
C              ENDS ARE ONE POINT HAS TWO JOINS, 2U-1 AND 2U, THE FIRST
C              FREE ONE IS GIVEN; ANY OTHER END HAS ITS OWN.
C     IE      (INPUT)  INTEGER  THE END (OF A PAD: 2U-1)
C     IS      (OUTPUT) INTEGER  THE FREE JOIN (KFLK(IS) = 0), 0: NONE
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMGFRE(IE, IS)
      IMPLICIT NONE
      INTEGER IE, IS
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM)
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI
      SAVE /CMITM/
C     ---- /CMTWK/ WORK SPACE OF THE TOUR: GRID, NEIGHBOURS, QUEUE -----
      INTEGER MXPT, MXCEL, MXNB
      PARAMETER (MXPT = 2 * MXITM, MXCEL = 2 * MXITM, MXNB = 16)
      INTEGER NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1        KQHD, KQN, KWORK, KWMAX,
     2        KQX(MXPT), KQY(MXPT), KCST(MXCEL + 1), KCCN(MXCEL),
     3        KCEL(MXPT), KSLT(MXPT), KNB(MXNB, MXPT), KQUE(MXITM),
     4        LQUE(MXITM)
      COMMON /CMTWK/ NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1               KQHD, KQN, KWORK, KWMAX, KQX, KQY, KCST, KCCN,
     2               KCEL, KSLT, KNB, KQUE, LQUE
      SAVE /CMTWK/
C     ---- /CMTWG/ THE GREEDY TOUR: WHICH END IS JOINED TO WHICH -------
      INTEGER KLNK(MXPT), KFLK(MXPT), KPTR(MXPT), KHP(MXPT),
     1        KUF(MXITM), KFSA(MXITM), KFSB(MXITM)
      COMMON /CMTWG/ KLNK, KFLK, KPTR, KHP, KUF, KFSA, KFSB
      SAVE /CMTWG/
C     ---- LOCAL -------------------------------------------------------
      INTEGER IA, IB
C
      IS = 0
      IA = IE - 1 + MOD(IE, 2)
      IB = IA + 1
      IF (KQX(IA) .EQ. KQX(IB) .AND. KQY(IA) .EQ. KQY(IB)) THEN
         IF (KFLK(IA) .EQ. 0) THEN
            IS = IA
         ELSE IF (KFLK(IB) .EQ. 0) THEN
            IS = IB
         END IF
      ELSE IF (KFLK(IE) .EQ. 0) THEN
         IS = IE
      END IF
      RETURN
C     END OF CMGFRE
      END
