C=======================================================================
C     MLNORM - THE OFFSET VECTORS OF A CONDUCTOR'S SEGMENTS     (M703L)
C     SOURCE:  RECONSTRUCTED. FOR EACH SEGMENT, ITS LEFT NORMAL OF
C              LENGTH R IN WHOLE 0.01 MM: OF THE FOUR LATTICE POINTS
C              AROUND THE EXACT VECTOR THE ONE WHOSE LENGTH IS NEAREST
C              R, SO THAT TWO OF THEM ARE EQUALLY LONG WITHIN 0.01 MM
C              AND AN ARC FROM ONE TO THE OTHER IS A VALID FRAME.
C     IC      (INPUT)  INTEGER           THE CONDUCTOR
C     R       (INPUT)  DOUBLE PRECISION  THE OFFSET, 0.01 MM
C     RESULT IN /MLWRK/: NSEG, JNX(I), JNY(I) FOR SEGMENT I
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE MLNORM(IC, R)
      IMPLICIT NONE
      INTEGER IC
      DOUBLE PRECISION R
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
C     ---- /MLWRK/ OFFSETS OF THE SEGMENTS OF A CONDUCTOR, ONE PASS ---
      INTEGER MXSEG
      PARAMETER (MXSEG = 200000)
      INTEGER NSEG, JNX(MXSEG), JNY(MXSEG)
      COMMON /MLWRK/ NSEG, JNX, JNY
      SAVE /MLWRK/
C     ---- LOCAL -------------------------------------------------------
      INTEGER I, IV, IA, IB, JA, JB, KA, KB
      DOUBLE PRECISION DX, DY, D, VX, VY, E, EBEST
C
      NSEG = 0
      DO 20 IV = KCV1(IC), KCV2(IC) - 1
         NSEG = NSEG + 1
         DX = KVX(IV+1) - KVX(IV)
         DY = KVY(IV+1) - KVY(IV)
         D = SQRT(DX * DX + DY * DY)
         VX = -DY / D * R
         VY = DX / D * R
C        THE WHOLE NUMBERS AT OR BELOW VX AND VY (FORTRAN 77 HAS NO
C        FLOOR: INT ROUNDS TOWARDS ZERO)
         IA = INT(VX)
         IF (DBLE(IA) .GT. VX) IA = IA - 1
         IB = INT(VY)
         IF (DBLE(IB) .GT. VY) IB = IB - 1
         EBEST = 1.0D30
         KA = NINT(VX)
         KB = NINT(VY)
         DO 10 I = 0, 3
            JA = IA + MOD(I, 2)
            JB = IB + I / 2
            E = ABS(SQRT(DBLE(JA)**2 + DBLE(JB)**2) - R)
            IF (E .LT. EBEST - 1.0D-9) THEN
               EBEST = E
               KA = JA
               KB = JB
            END IF
   10    CONTINUE
         JNX(NSEG) = KA
         JNY(NSEG) = KB
   20 CONTINUE
      RETURN
C     END OF MLNORM
      END
