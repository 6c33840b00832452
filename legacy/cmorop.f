C=======================================================================
C     CMOROP - OR-OPT: MOVE ONE TO THREE ITEMS ELSEWHERE IN THE TOUR
C                                                               (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMTOUR). THE SEGMENT S OF K ITEMS
C              STARTING AT ITEM M (K = 1, 2, 3) IS TAKEN OUT AND PUT
C              BETWEEN THE ITEMS AT PLACES C AND C+1, DRAWN FORWARD OR
C              BACKWARD, WHEN THAT SHORTENS THE TOUR. C IS FOUND FROM
C              THE NEAREST ENDS (KNB) OF THE TWO ENDS OF S THAT ARE
C              NEARER TO IT THAN WHAT TAKING S OUT SAVES. THE MOVE IS
C              MADE BY THREE REVERSALS OF THE TOUR (CMRUNM).
C     M       (INPUT)  INTEGER  THE FIRST ITEM OF THE SEGMENT
C     LIMP    (OUTPUT) INTEGER  1 IF THE TOUR WAS CHANGED, ELSE 0
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMOROP(M, LIMP)
      IMPLICIT NONE
      INTEGER M, LIMP
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM), NJOB
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI, NJOB
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
C     ---- /CMTWJ/ WHAT A KICK (CMKICK) HAS CHANGED, TO PUT IT BACK, AND
C     THE LENGTH THE MOVES SINCE THE KICK HAVE TAKEN OFF THE TOUR ------
      INTEGER MXJRN
      PARAMETER (MXJRN = 20000)
      INTEGER NJRN, LJRN, KJWK, KJLO, KJHI, KJIT(MXITM), KJOR(MXITM)
      DOUBLE PRECISION DGAIN
      COMMON /CMTWJ/ DGAIN, NJRN, LJRN, KJWK, KJLO, KJHI, KJIT, KJOR
      SAVE /CMTWJ/
C     ---- /CMTWM/ THE LENGTH OF EACH END'S MOVE (CMDMV), AND THE OLD
C     LENGTHS A KICK HAS CHANGED: NDJ PAIRS, THE END KDJE(J) AND THE
C     LENGTH DDJV(J) IT HAD (TWO PAIRS A MOVE, AT MOST TWO MOVES A
C     REVERSAL, AT MOST MXJRN REVERSALS A KICK) -----------------------
      INTEGER MXDJ
      PARAMETER (MXDJ = 4 * MXJRN + 16)
      INTEGER NDJ, KDJE(MXDJ)
      DOUBLE PRECISION DMV(MXPT + 2), DDJV(MXDJ)
      COMMON /CMTWM/ DMV, DDJV, NDJ, KDJE
      SAVE /CMTWM/
C     ---- LOCAL -------------------------------------------------------
      INTEGER I, J2, K, L, IEND, ID, IQ, M2, J, IC, IREV, NB, IBC,
     1        IBREV, IXS, IYS, IXE, IYE, IXP, IYP, IXN, IYN, IXC, IYC,
     2        IXD, IYD, IE4, MS(7)
      LOGICAL LEXIT, LONE
      INTEGER IROLE
      DOUBLE PRECISION REM, ADD, GAIN, BEST, DIST, DPS
      INTEGER JX1, JY1, JX2, JY2
      INTEGER KIN, KOUT, MM
C     THE DISTANCE OF TWO POINTS: A STATEMENT FUNCTION, NO CALL
      DIST(JX1, JY1, JX2, JY2) = SQRT((DBLE(JX1) - JX2)**2 +
     1   (DBLE(JY1) - JY2)**2)
C     THE END ITEM MM IS ENTERED BY, AND THE END IT IS LEFT BY, AS IT
C     IS DRAWN NOW (CMEND'S RULE)
      KIN(MM) = 2 * MM - 1 + IORI(MM)
      KOUT(MM) = 2 * MM - IORI(MM)
C
      LIMP = 0
      I = IPOS(M)
C     THE START OF S, AND THE MOVE INTO IT
C     (CMEND'S LOOK-UPS ARE WRITTEN OUT HERE: CMOROP IS CALLED FOR
C     EVERY ITEM THE REPAIRS LOOK AT)
      IE4 = KIN(M)
      IXS = KQX(IE4)
      IYS = KQY(IE4)
      IF (I .GT. 1) THEN
         IE4 = KOUT(ITOUR(I - 1))
         IXP = KQX(IE4)
         IYP = KQY(IE4)
      ELSE
         IXP = KDSX
         IYP = KDSY
      END IF
C     (EVERY MOVE TAKEN OUT HERE HAS ITS LENGTH IN DMV, CMDMV)
      DPS = DMV(KIN(M))
      DO 50 K = 1, 3
         J2 = I + K - 1
         IF (J2 .GT. NITM) RETURN
C        THE END OF S, AND THE MOVE OUT OF IT
         IE4 = KOUT(ITOUR(J2))
         IXE = KQX(IE4)
         IYE = KQY(IE4)
         IF (J2 .LT. NITM) THEN
            IE4 = KIN(ITOUR(J2 + 1))
            IXN = KQX(IE4)
            IYN = KQY(IE4)
         ELSE
            IXN = KDTX
            IYN = KDTY
         END IF
         REM = DPS + DMV(KOUT(ITOUR(J2)))
     1       - DIST(IXP, IYP, IXN, IYN)
         IF (REM .LE. 1.0D-6) GOTO 50
         BEST = 1.0D-6
         IBC = -1
         IBREV = 0
C        ---- CANDIDATES FROM THE NEAREST ENDS OF BOTH ENDS OF S -------
         DO 40 IEND = 1, 2
            IF (IEND .EQ. 1) THEN
               ID = KIN(ITOUR(I))
            ELSE
               ID = KOUT(ITOUR(J2))
            END IF
            DO 30 NB = 1, MXNB
               IQ = KNB(NB, ID)
               IF (IQ .EQ. 0) GOTO 40
C              THE NEW MOVE TO OR FROM S MUST BE SHORTER THAN WHAT
C              TAKING S OUT SAVES; THE NEIGHBOURS ARE NEAREST FIRST
               IF (DNB(NB, ID) .GE. REM)
     1            GOTO 40
               M2 = (IQ + 1) / 2
               J = IPOS(M2)
               IF (J .GE. I .AND. J .LE. J2) GOTO 30
               LEXIT = IQ .EQ. KOUT(M2)
               LONE = KQX(2*M2) .EQ. KQX(2*M2-1) .AND.
     1                KQY(2*M2) .EQ. KQY(2*M2-1)
               IROLE = 0
C              WHERE IT GOES, AND WHETHER S IS TURNED ROUND (AN ITEM
C              WHOSE ENDS ARE ONE POINT IS TRIED IN BOTH ROLES)
   25          CONTINUE
               IF (LONE) LEXIT = IROLE .EQ. 0
               IF (LEXIT) THEN
                  IC = J
               ELSE
                  IC = J - 1
               END IF
               IREV = 0
               IF ((IEND .EQ. 1) .NEQV. LEXIT) IREV = 1
               IF (IC .GE. I - 1 .AND. IC .LE. J2) GOTO 28
C              IQ IS ONE OF THE TWO ENDS S GOES BETWEEN
C              (CMEND'S LOOK-UP WRITTEN OUT: THE INNERMOST LOOP)
               IF (LEXIT) THEN
                  IXC = KQX(IQ)
                  IYC = KQY(IQ)
                  IF (IC .LT. NITM) THEN
                     IE4 = KIN(ITOUR(IC + 1))
                     IXD = KQX(IE4)
                     IYD = KQY(IE4)
                  ELSE
                     IXD = KDTX
                     IYD = KDTY
                  END IF
               ELSE
                  IF (IC .GE. 1) THEN
                     IE4 = KOUT(ITOUR(IC))
                     IXC = KQX(IE4)
                     IYC = KQY(IE4)
                  ELSE
                     IXC = KDSX
                     IYC = KDSY
                  END IF
                  IXD = KQX(IQ)
                  IYD = KQY(IQ)
               END IF
               IF (IREV .EQ. 0) THEN
                  ADD = DIST(IXC, IYC, IXS, IYS) +
     1                  DIST(IXE, IYE, IXD, IYD)
               ELSE
                  ADD = DIST(IXC, IYC, IXE, IYE) +
     1                  DIST(IXS, IYS, IXD, IYD)
               END IF
               IF (IC .GE. 1) THEN
                  ADD = ADD - DMV(KOUT(ITOUR(IC)))
               ELSE
                  ADD = ADD - DMV(2 * NITM + 1)
               END IF
               GAIN = REM - ADD
               IF (GAIN .GT. BEST) THEN
                  BEST = GAIN
                  IBC = IC
                  IBREV = IREV
               END IF
   28          CONTINUE
               IROLE = IROLE + 1
               IF (LONE .AND. IROLE .EQ. 1) GOTO 25
   30       CONTINUE
   40    CONTINUE
         IF (IBC .LT. 0) GOTO 50
C        ---- MAKE THE MOVE; QUEUE THE ITEMS WHOSE NEIGHBOURS CHANGE ---
         DO 45 L = 1, 7
            MS(L) = 0
   45    CONTINUE
         IF (I .GT. 1) MS(1) = ITOUR(I - 1)
         IF (J2 .LT. NITM) MS(2) = ITOUR(J2 + 1)
         IF (IBC .GE. 1) MS(3) = ITOUR(IBC)
         IF (IBC .LT. NITM) MS(4) = ITOUR(IBC + 1)
         DO 46 L = 1, K
            MS(4 + L) = ITOUR(I + L - 1)
   46    CONTINUE
         CALL CMRUNM(I, J2, IBC, IBREV)
         DO 48 L = 1, 7
            IF (MS(L) .NE. 0) CALL CMQPSH(MS(L))
   48    CONTINUE
         DGAIN = DGAIN + BEST
         LIMP = 1
         RETURN
   50 CONTINUE
      RETURN
C     END OF CMOROP
      END
