C=======================================================================
C     CMKNN  - THE NEAREST ENDS OF EVERY END, FOR 2-OPT        (SHARED)
C     SOURCE:  RECONSTRUCTED. FOR EACH END, THE MXNB NEAREST ENDS OF
C              OTHER ITEMS, NEAREST FIRST, IN KNB (0 WHERE THERE ARE
C              FEWER). THE GRID HOLDS ALL ENDS.
C     NP      (INPUT)  INTEGER  NUMBER OF ENDS
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMKNN(NP)
      IMPLICIT NONE
      INTEGER NP
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
C     ---- LOCAL -------------------------------------------------------
      INTEGER IP, IC, ICX, ICY, K, IGX, IGY, IS, IQ, ISTEP, KMAX, N, J,
     1        NBI(MXNB)
      DOUBLE PRECISION D, RK, NBD(MXNB), CMRBND
      EXTERNAL CMRBND
C
      KMAX = MAX(NGX, NGY)
      DO 60 IP = 1, NP
         N = 0
         CALL CMCELL(KQX(IP), KQY(IP), IC)
         ICX = MOD(IC - 1, NGX)
         ICY = (IC - 1) / NGX
         DO 40 K = 0, KMAX
            DO 30 IGY = ICY - K, ICY + K
               IF (IGY .LT. 0 .OR. IGY .GE. NGY) GOTO 30
               ISTEP = 2 * K
               IF (IGY .EQ. ICY - K .OR. IGY .EQ. ICY + K) ISTEP = 1
               IF (ISTEP .EQ. 0) ISTEP = 1
               DO 20 IGX = ICX - K, ICX + K, ISTEP
                  IF (IGX .LT. 0 .OR. IGX .GE. NGX) GOTO 20
                  IC = IGX + IGY * NGX + 1
                  DO 10 IS = KCST(IC), KCST(IC) + KCCN(IC) - 1
                     IQ = KCEL(IS)
                     D = (DBLE(KQX(IQ)) - KQX(IP))**2 +
     1                   (DBLE(KQY(IQ)) - KQY(IP))**2
C                    A FULL LIST TAKES ONLY A NEARER END
                     IF (N .EQ. MXNB) THEN
                        IF (D .GT. NBD(N)) GOTO 10
                     END IF
C                    NOT ITSELF, NOT THE OTHER END OF ITS OWN ITEM,
C                    AND AN ITEM WHOSE ENDS ARE ONE POINT ONLY ONCE
                     IF ((IQ + 1) / 2 .EQ. (IP + 1) / 2) GOTO 10
                     IF (MOD(IQ, 2) .EQ. 0) THEN
                        IF (KQX(IQ) .EQ. KQX(IQ-1) .AND.
     1                      KQY(IQ) .EQ. KQY(IQ-1)) GOTO 10
                     END IF
                     CALL CMKINS(NBI, NBD, N, MXNB, IQ, D)
   10             CONTINUE
   20          CONTINUE
   30       CONTINUE
            RK = CMRBND(KQX(IP), KQY(IP), ICX, ICY, K)
            IF (RK .GE. 1.0D299) GOTO 45
            IF (N .EQ. MXNB) THEN
               IF (NBD(N) .LE. RK * RK) GOTO 45
            END IF
   40    CONTINUE
   45    CONTINUE
         DO 50 J = 1, MXNB
            KNB(J, IP) = 0
            IF (J .LE. N) KNB(J, IP) = NBI(J)
   50    CONTINUE
   60 CONTINUE
      RETURN
C     END OF CMKNN
      END
