C=======================================================================
C     CMLCL3 - WHICH 3-OPT MOVE SIX ENDS MAKE, IF ANY     (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMLK3). THE MOVES OUT ARE P1-P2,
C              P3-P4, P5-P6 (PLACES OF THE CYCLE OF ENDS, EACH PAIR 2B
C              AND 2B+1: THE MOVE AFTER TOUR PLACE B), THE MOVES IN
C              P2-P3, P4-P5, P6-P1. WITH THE THREE MOVES OUT AFTER
C              PLACES A .LT. B .LT. C THE TOUR IS S X Y E, X THE ITEMS
C              A+1..B AND Y THE ITEMS B+1..C; THE FOUR 3-OPT MOVES THAT
C              TAKE OUT ALL THREE ARE S X' Y' E (TYPE 1), S Y X E (2),
C              S Y' X E (3) AND S Y X' E (4), ' DRAWN BACKWARD. EACH
C              END IS NAMED BY ITS MOVE'S RANK (0, 1, 2) AND SIDE (0
C              BEFORE, 1 AFTER), 2*RANK+SIDE; A MOVE IN BY 6*LOW+HIGH
C              OF ITS TWO NAMES; THE THREE SORTED NAME THE TYPE.
C     IP1..IP6 (INPUT) INTEGER  THE SIX PLACES, THREE DIFFERENT MOVES
C     ITYP    (OUTPUT) INTEGER  THE TYPE, 1..4, OR 0: NO TOUR
C     IBA, IBB, IBC (OUTPUT) INTEGER  A, B AND C
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMLCL3(IP1, IP2, IP3, IP4, IP5, IP6, ITYP, IBA,
     1                  IBB, IBC)
      IMPLICIT NONE
      INTEGER IP1, IP2, IP3, IP4, IP5, IP6, ITYP, IBA, IBB, IBC
C     ---- LOCAL -------------------------------------------------------
      INTEGER IB(3), L(6), IC(3), IPS(6), I, J, K, IR
C
      IB(1) = IP1 / 2
      IB(2) = IP3 / 2
      IB(3) = IP5 / 2
      IBA = MIN(IB(1), IB(2), IB(3))
      IBC = MAX(IB(1), IB(2), IB(3))
      IBB = IB(1) + IB(2) + IB(3) - IBA - IBC
      IPS(1) = IP1
      IPS(2) = IP2
      IPS(3) = IP3
      IPS(4) = IP4
      IPS(5) = IP5
      IPS(6) = IP6
      DO 10 I = 1, 6
         IR = 2
         IF (IPS(I) / 2 .EQ. IBA) IR = 0
         IF (IPS(I) / 2 .EQ. IBB) IR = 1
         L(I) = 2 * IR + MOD(IPS(I), 2)
   10 CONTINUE
      IC(1) = 6 * MIN(L(2), L(3)) + MAX(L(2), L(3))
      IC(2) = 6 * MIN(L(4), L(5)) + MAX(L(4), L(5))
      IC(3) = 6 * MIN(L(6), L(1)) + MAX(L(6), L(1))
C     SORT THE THREE
      DO 30 I = 1, 2
         DO 20 J = I + 1, 3
            IF (IC(J) .LT. IC(I)) THEN
               K = IC(I)
               IC(I) = IC(J)
               IC(J) = K
            END IF
   20    CONTINUE
   30 CONTINUE
      ITYP = 0
      IF (IC(1) .EQ. 2 .AND. IC(2) .EQ. 10 .AND. IC(3) .EQ. 23) ITYP = 1
      IF (IC(1) .EQ. 3 .AND. IC(2) .EQ. 10 .AND. IC(3) .EQ. 17) ITYP = 2
      IF (IC(1) .EQ. 4 .AND. IC(2) .EQ. 9 .AND. IC(3) .EQ. 17) ITYP = 3
      IF (IC(1) .EQ. 3 .AND. IC(2) .EQ. 11 .AND. IC(3) .EQ. 16) ITYP = 4
      RETURN
C     END OF CMLCL3
      END
