C=======================================================================
C     CMGSFT - SIFT AN END DOWN THE HEAP OF CMGJN               (SHARED)
C     SOURCE:  RECONSTRUCTED (A BINARY HEAP, WILLIAMS 1964). THE END AT
C              KHP(I0) GOES DOWN UNTIL NO END BELOW IT COMES FIRST. END
C              A COMES BEFORE END B WHEN ITS NEXT MOVE IS SHORTER, OR AS
C              LONG AND A .LT. B: THE ORDER IS TOTAL, SO THE JOINS DO
C              NOT DEPEND ON HOW THE HEAP WAS FILLED.
C     NH      (INPUT)  INTEGER  ENDS IN THE HEAP KHP(1..NH)
C     I0      (INPUT)  INTEGER  THE PLACE OF THE END TO SIFT
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMGSFT(NH, I0)
      IMPLICIT NONE
      INTEGER NH, I0
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
C     ---- /CMTWD/ THE LENGTH FROM EACH END TO EACH OF ITS NEAR ENDS --
      DOUBLE PRECISION DNB(MXNB, MXPT)
      COMMON /CMTWD/ DNB
      SAVE /CMTWD/
C     ---- /CMTWG/ THE GREEDY TOUR: WHICH END IS JOINED TO WHICH -------
      INTEGER KLNK(MXPT), KFLK(MXPT), KPTR(MXPT), KHP(MXPT),
     1        KUF(MXITM), KFSA(MXITM), KFSB(MXITM)
      COMMON /CMTWG/ KLNK, KFLK, KPTR, KHP, KUF, KFSA, KFSB
      SAVE /CMTWG/
C     ---- LOCAL -------------------------------------------------------
      INTEGER I, J, IE, JE, JE2
      DOUBLE PRECISION DE, DJ, DJ2
C
      I = I0
      IE = KHP(I)
      DE = DNB(KPTR(IE), IE)
   10 CONTINUE
      J = 2 * I
      IF (J .GT. NH) GOTO 20
      JE = KHP(J)
      DJ = DNB(KPTR(JE), JE)
      IF (J .LT. NH) THEN
         JE2 = KHP(J + 1)
         DJ2 = DNB(KPTR(JE2), JE2)
         IF (DJ2 .LT. DJ .OR. (DJ2 .EQ. DJ .AND. JE2 .LT. JE)) THEN
            J = J + 1
            JE = JE2
            DJ = DJ2
         END IF
      END IF
      IF (DJ .GT. DE .OR. (DJ .EQ. DE .AND. JE .GT. IE)) GOTO 20
      KHP(I) = JE
      I = J
      GOTO 10
   20 CONTINUE
      KHP(I) = IE
      RETURN
C     END OF CMGSFT
      END
