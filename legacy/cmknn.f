C=======================================================================
C     CMKNN  - THE NEAREST ENDS OF EVERY END, FOR 2-OPT        (SHARED)
C     SOURCE:  RECONSTRUCTED. FOR EACH END, MXNB ENDS OF OTHER ITEMS,
C              NEAREST FIRST, IN KNB (0 WHERE THERE ARE FEWER): THE
C              MXQ NEAREST IN EACH OF THE FOUR QUADRANTS AROUND IT
C              (LOOKED FOR WITHIN MXRING RINGS OF GRID CELLS, AND AT
C              MOST MXQEN ENDS BEYOND THOSE THE NEAREST NEEDED), AND THE
C              NEAREST OTHERS TO FILL THE LIST. ON A BOARD OF CLUSTERS
C              THE NEAREST ENDS ALL LIE IN AN END'S OWN CLUSTER, AND
C              NO MOVE COULD THEN JOIN TWO CLUSTERS BETTER; THE
C              QUADRANTS GIVE EACH END NEIGHBOURS ON EVERY SIDE. THE
C              GRID HOLDS ALL ENDS BUT THE EXIT OF AN ITEM WHOSE ENDS
C              ARE ONE POINT (CMTOUR): SUCH AN EXIT TAKES THE LIST OF
C              ITS ENTRY.
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
C     ---- /CMTWG/ THE GRID OF THE NEAR ENDS, CELL BY CELL (CMKNN) ----
      INTEGER KCX(MXPT), KCY(MXPT)
      COMMON /CMTWG/ KCX, KCY
      SAVE /CMTWG/
C     ---- LOCAL -------------------------------------------------------
      INTEGER MXQ, MXRING, MXQEN
      PARAMETER (MXQ = 2, MXRING = 30, MXQEN = 4000)
      INTEGER IP, IC, ICX, ICY, K, IGX, IGY, IS, IQ, ISTEP, KMAX, N, J,
     1        NBI(MXNB), NQ(4), KQB(MXQ, 4), IQD, IDX, IDY, NF,
     2        L, NBF(MXNB), NEX, NEX16, IBX1, IBX2, IBY1, IBY2, MATE,
     3        IPX, IPY
      DOUBLE PRECISION D, RK, NBD(MXNB), QBD(MXQ, 4), DF(MXNB), CMRBND
      LOGICAL LDONE, LOUT(4)
      EXTERNAL CMRBND
C
      KMAX = MAX(NGX, NGY)
C     THE BOX OF THE ENDS: NO END LIES IN A QUADRANT BEYOND IT
      IBX1 = KQX(1)
      IBX2 = KQX(1)
      IBY1 = KQY(1)
      IBY2 = KQY(1)
      DO 2 IP = 1, NP
         IBX1 = MIN(IBX1, KQX(IP))
         IBX2 = MAX(IBX2, KQX(IP))
         IBY1 = MIN(IBY1, KQY(IP))
         IBY2 = MAX(IBY2, KQY(IP))
    2 CONTINUE
C     EACH SLOT OF THE GRID GETS ITS END'S POINT (KCX, KCY), SO THAT A
C     CELL IS READ FROM ONE STRETCH OF STORE RATHER THAN FROM ENDS ALL
C     OVER THE TABLES
      DO 8 IS = 1, KCST(NGX * NGY + 1) - 1
         KCX(IS) = KQX(KCEL(IS))
         KCY(IS) = KQY(KCEL(IS))
    8 CONTINUE
      DO 60 IP = 1, NP
C        THE EXIT OF AN ITEM WHOSE ENDS ARE ONE POINT (A PAD) HAS THE
C        LIST OF ITS ENTRY, FOUND JUST BEFORE: THE SAME POINT, THE SAME
C        ITEM LEFT OUT, THE SAME ENDS LOOKED AT IN THE SAME ORDER
         IF (MOD(IP, 2) .EQ. 0) THEN
            IF (KQX(IP) .EQ. KQX(IP - 1) .AND.
     1          KQY(IP) .EQ. KQY(IP - 1)) THEN
               DO 3 J = 1, MXNB
                  KNB(J, IP) = KNB(J, IP - 1)
                  DNB(J, IP) = DNB(J, IP - 1)
    3          CONTINUE
               GOTO 60
            END IF
         END IF
         IPX = KQX(IP)
         IPY = KQY(IP)
         MATE = IP + 1
         IF (MOD(IP, 2) .EQ. 0) MATE = IP - 1
         N = 0
         NEX = 0
         NEX16 = -1
         DO 5 J = 1, 4
            NQ(J) = 0
    5    CONTINUE
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
                  NEX = NEX + KCCN(IC)
                  DO 10 IS = KCST(IC), KCST(IC) + KCCN(IC) - 1
                     IQ = KCEL(IS)
C                    NOT ITSELF, NOT THE OTHER END OF ITS OWN ITEM
                     IF (IQ .EQ. IP .OR. IQ .EQ. MATE) GOTO 10
                     IDX = KCX(IS) - IPX
                     IDY = KCY(IS) - IPY
                     D = DBLE(IDX)**2 + DBLE(IDY)**2
C                    ONLY AN END THAT CAN ENTER THE LIST IS OFFERED TO
C                    IT (CMKINS BREAKS A TIE OF LENGTHS)
                     IF (N .LT. MXNB) THEN
                        CALL CMKINS(NBI, NBD, N, MXNB, IQ, D)
                     ELSE IF (D .LE. NBD(MXNB)) THEN
                        CALL CMKINS(NBI, NBD, N, MXNB, IQ, D)
                     END IF
C                    ITS QUADRANT: 1 RIGHT AND UP, 2 LEFT AND UP, 3 LEFT
C                    AND DOWN, 4 RIGHT AND DOWN (AN END AT THE SAME
C                    POINT IS IN NONE)
                     IF (IDX .GT. 0 .AND. IDY .GE. 0) THEN
                        IQD = 1
                     ELSE IF (IDX .LE. 0 .AND. IDY .GT. 0) THEN
                        IQD = 2
                     ELSE IF (IDX .LT. 0 .AND. IDY .LE. 0) THEN
                        IQD = 3
                     ELSE IF (IDX .GE. 0 .AND. IDY .LT. 0) THEN
                        IQD = 4
                     ELSE
                        GOTO 10
                     END IF
                     IF (NQ(IQD) .LT. MXQ) THEN
                        CALL CMKINS(KQB(1, IQD), QBD(1, IQD), NQ(IQD),
     1                              MXQ, IQ, D)
                     ELSE IF (D .LE. QBD(MXQ, IQD)) THEN
                        CALL CMKINS(KQB(1, IQD), QBD(1, IQD), NQ(IQD),
     1                              MXQ, IQ, D)
                     END IF
   10             CONTINUE
   20          CONTINUE
   30       CONTINUE
C           DONE WHEN NO END BEYOND RING K CAN ENTER A LIST: THE
C           NEAREST ARE FOUND, AND EACH QUADRANT'S TOO, OR RING MXRING
C           IS PASSED
            RK = CMRBND(KQX(IP), KQY(IP), ICX, ICY, K)
            IF (RK .GE. 1.0D299) GOTO 45
            IF (N .LT. MXNB) GOTO 40
            IF (NBD(N) .GT. RK * RK) GOTO 40
            IF (K .GE. MXRING) GOTO 45
C           THE NEAREST ARE FOUND: THE QUADRANTS' SEARCH LOOKS AT
C           MXQEN MORE ENDS AT MOST (WHOLE RINGS), SO THAT ENDS IN A
C           ROW, WHOSE CELLS HOLD MANY AND WHOSE QUADRANTS ACROSS THE
C           ROW ARE EMPTY, DO NOT SEARCH MXRING RINGS OF FULL CELLS
            IF (NEX16 .LT. 0) NEX16 = NEX
            IF (NEX - NEX16 .GT. MXQEN) GOTO 45
C           A QUADRANT IS DONE WHEN ITS MXQ NEAREST ARE FOUND, OR WHEN
C           NO END CAN BE IN IT BEYOND RING K: NO CELL OF IT LIES THERE,
C           OR THE END IS ON THE BOX'S SIDE THE QUADRANT LIES BEYOND (AN
C           END NEAR THE EDGE, OR IN A ROW OF ENDS, HAS QUADRANTS WITH
C           FEW ENDS OR NONE, NOT SEARCHED ON)
            LOUT(1) = (ICX + K + 1 .GT. NGX - 1 .AND.
     1                 ICY + K + 1 .GT. NGY - 1) .OR. KQX(IP) .GE. IBX2
            LOUT(2) = (ICX - K - 1 .LT. 0 .AND.
     1                 ICY + K + 1 .GT. NGY - 1) .OR. KQY(IP) .GE. IBY2
            LOUT(3) = (ICX - K - 1 .LT. 0 .AND.
     1                 ICY - K - 1 .LT. 0) .OR. KQX(IP) .LE. IBX1
            LOUT(4) = (ICX + K + 1 .GT. NGX - 1 .AND.
     1                 ICY - K - 1 .LT. 0) .OR. KQY(IP) .LE. IBY1
            LDONE = .TRUE.
            DO 35 J = 1, 4
               IF (LOUT(J)) GOTO 35
               IF (NQ(J) .LT. MXQ) THEN
                  LDONE = .FALSE.
               ELSE IF (QBD(MXQ, J) .GT. RK * RK) THEN
                  LDONE = .FALSE.
               END IF
   35       CONTINUE
            IF (LDONE) GOTO 45
   40    CONTINUE
   45    CONTINUE
C        ---- THE LIST: THE QUADRANTS' ENDS, THEN THE NEAREST OTHERS ---
         NF = 0
         DO 47 J = 1, 4
            DO 46 L = 1, NQ(J)
               CALL CMKINS(NBF, DF, NF, MXNB, KQB(L, J), QBD(L, J))
   46       CONTINUE
   47    CONTINUE
         DO 49 J = 1, N
            IF (NF .GE. MXNB) GOTO 49
            DO 48 L = 1, NF
               IF (NBF(L) .EQ. NBI(J)) GOTO 49
   48       CONTINUE
            CALL CMKINS(NBF, DF, NF, MXNB, NBI(J), NBD(J))
   49    CONTINUE
         DO 50 J = 1, MXNB
            KNB(J, IP) = 0
            DNB(J, IP) = 0.0D0
            IF (J .LE. NF) THEN
               KNB(J, IP) = NBF(J)
C              THE ROOT OF THE SUM OF SQUARES FOUND ABOVE: THE SAME
C              DIFFERENCES (EXACT), THE SAME SQUARES, ADDED IN THE SAME
C              ORDER AS IN THE DIST OF CMOPT2 AND CMOROP, SO THE SAME
C              LENGTH TO THE LAST BIT
               DNB(J, IP) = SQRT(DF(J))
            END IF
   50    CONTINUE
   60 CONTINUE
      RETURN
C     END OF CMKNN
      END
