C=======================================================================
C     CMGRDY - THE FIRST TOUR: GREEDY MATCHING OF THE ENDS      (SHARED)
C     SOURCE:  RECONSTRUCTED, DOCS/RECONSTRUCTION.MD (ORDER). THE MOVES
C              BETWEEN ITEMS ARE CHOSEN SHORTEST FIRST (CMGJN, AMONG
C              EACH END'S NEAR ENDS), WHICH LEAVES CHAINS OF ITEMS;
C              THE FREE ENDS OF THE CHAINS ARE THEN JOINED THE SAME WAY,
C              ROUND AFTER ROUND, UNTIL ONE CHAIN IS LEFT. ITS TWO ENDS
C              ARE JOINED INTO A LOOP, AND THE LOOP IS OPENED WHERE
C              GOING OUT FROM (KDSX, KDSY) AND BACK TO (KDTX, KDTY)
C              ADDS LEAST. A GREEDY TOUR HAS FEWER LONG MOVES BACK
C              ACROSS THE BOARD THAN A NEAREST NEIGHBOUR'S, WHICH THE
C              2-OPT AND OR-OPT MOVES AND THE KICKS CAN SELDOM MEND
C              (JOHNSON AND MCGEOCH, DOCS/SOURCES.MD).
C     IN:  KQX, KQY (THE ENDS OF THE NITM ITEMS: 2I-1 THE ENTRY OF ITEM
C          I DRAWN FORWARD, 2I ITS EXIT), KDSX, KDSY, KDTX, KDTY.
C     OUT: ITOUR, IPOS, IORI: THE TOUR; KQX, KQY AS ON ENTRY.
C     WORK: THE GRID AND THE NEAR ENDS (CMGRID, CMKNN), /CMTWG/.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMGRDY
      IMPLICIT NONE
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
      INTEGER NP, I, IU, IV, IS, NF, NRND, N, IP, IPBEST, IDIR, IBEST,
     1        IX1, IY1, IX2, IY2, IX3, IY3, IX4, IY4
      DOUBLE PRECISION DCOST, DBEST, DIST
      INTEGER JX1, JY1, JX2, JY2
C     THE DISTANCE OF TWO POINTS: A STATEMENT FUNCTION, NO CALL
      DIST(JX1, JY1, JX2, JY2) = SQRT((DBLE(JX1) - JX2)**2 +
     1   (DBLE(JY1) - JY2)**2)
C
      IF (NITM .EQ. 0) RETURN
C     ---- 1. THE ITEMS' ENDS JOINED SHORTEST FIRST (THE FIRST TEN OF
C     EACH END'S 16 NEAR ENDS: OF 8, 10 AND 16, THE BEST MEASURED ON
C     TSPLIB'S DRILLING PROBLEMS) ------------------------------------
      NP = 2 * NITM
      DO 10 I = 1, NP
         KCEL(I) = I
         KFLK(I) = 0
   10 CONTINUE
      CALL CMGRID(NP, 3)
      CALL CMKNN(NP)
      DO 12 I = 1, NITM
         KUF(I) = I
   12 CONTINUE
      CALL CMGJN(NITM, 10)
      DO 14 I = 1, NP
         KLNK(I) = KFLK(I)
   14 CONTINUE
      NRND = 0
C     ---- 2. THE CHAINS: EACH FROM ONE FREE END TO THE OTHER ----------
C     (IPOS MARKS THE ITEMS ALREADY IN A CHAIN; THERE ARE NO LOOPS, SO
C     EVERY CHAIN HAS TWO FREE ENDS: KFSA(F) AND KFSB(F))
   20 CONTINUE
      NRND = NRND + 1
      DO 22 I = 1, NITM
         IPOS(I) = 0
   22 CONTINUE
      NF = 0
      DO 30 IU = 1, NITM
         IF (IPOS(IU) .NE. 0) GOTO 30
         IF (KLNK(2 * IU - 1) .NE. 0 .AND. KLNK(2 * IU) .NE. 0) GOTO 30
         NF = NF + 1
         IS = 2 * IU - 1
         IF (KLNK(IS) .NE. 0) IS = 2 * IU
         KFSA(NF) = IS
         IV = IU
   25    CONTINUE
         IPOS(IV) = NF
C        OUT BY THE ITEM'S OTHER END, INTO THE NEXT ITEM
         IS = IS + 1 - 2 * MOD(IS + 1, 2)
         IF (KLNK(IS) .EQ. 0) THEN
            KFSB(NF) = IS
            GOTO 30
         END IF
         IS = KLNK(IS)
         IV = (IS + 1) / 2
         GOTO 25
   30 CONTINUE
      IF (NF .LE. 1) GOTO 50
      IF (NRND .GT. 40) THEN
C        A BOUND, NOT REACHED ON ANY BOARD TRIED: THE CHAINS END TO END
         DO 32 I = 1, NF - 1
            KLNK(KFSB(I)) = KFSA(I + 1)
            KLNK(KFSA(I + 1)) = KFSB(I)
   32    CONTINUE
         GOTO 20
      END IF
C     ---- 3. THE CHAINS AS UNITS, BY THEIR FREE ENDS: JOINED AGAIN ----
      DO 40 I = 1, NF
         CALL CMGPT(KFSA(I), KQX(2 * I - 1), KQY(2 * I - 1))
         CALL CMGPT(KFSB(I), KQX(2 * I), KQY(2 * I))
         KUF(I) = I
         KCEL(2 * I - 1) = 2 * I - 1
         KCEL(2 * I) = 2 * I
         KFLK(2 * I - 1) = 0
         KFLK(2 * I) = 0
   40 CONTINUE
      CALL CMGRID(2 * NF, 3)
      CALL CMKNN(2 * NF)
      CALL CMGJN(NF, MXNB)
      DO 45 IS = 1, 2 * NF
         IF (KFLK(IS) .EQ. 0) GOTO 45
         IF (MOD(IS, 2) .EQ. 1) THEN
            IU = KFSA((IS + 1) / 2)
         ELSE
            IU = KFSB(IS / 2)
         END IF
         IF (MOD(KFLK(IS), 2) .EQ. 1) THEN
            IV = KFSA((KFLK(IS) + 1) / 2)
         ELSE
            IV = KFSB(KFLK(IS) / 2)
         END IF
         KLNK(IU) = IV
   45 CONTINUE
      GOTO 20
C     ---- 4. THE ONE CHAIN, FROM KFSA(1): ENTERED BY END 2I-1, AN ITEM
C     IS DRAWN FORWARD (IORI = 0) ------------------------------------
   50 CONTINUE
      DO 52 I = 1, NITM
         KQX(2 * I - 1) = IEX(I)
         KQY(2 * I - 1) = IEY(I)
         KQX(2 * I) = IXX(I)
         KQY(2 * I) = IXY(I)
   52 CONTINUE
      IS = KFSA(1)
      N = 0
   55 CONTINUE
      N = N + 1
      IU = (IS + 1) / 2
      ITOUR(N) = IU
      IORI(IU) = MOD(IS + 1, 2)
      IF (N .LT. NITM) THEN
         IS = KLNK(IS + 1 - 2 * MOD(IS + 1, 2))
         GOTO 55
      END IF
C     ---- 5. WHERE TO OPEN THE LOOP, AND WHICH WAY ROUND --------------
C     OPENED BEFORE PLACE IP AND DRAWN FORWARD: FROM THE START TO THE
C     ENTRY OF IP, ROUND TO THE EXIT OF IP-1, TO THE END POINT. DRAWN
C     BACKWARD: FROM THE START TO THE EXIT OF IP, ROUND BACKWARD TO THE
C     ENTRY OF IP+1, TO THE END POINT. THE LEAST ADDED WINS; TIES: THE
C     SMALLER PLACE, FORWARD FIRST.
      IBEST = 1
      IPBEST = 1
      DBEST = 0.0D0
      DO 60 IP = 1, NITM
         IV = IP - 1
         IF (IV .EQ. 0) IV = NITM
         CALL CMGPT(2 * ITOUR(IP) - 1 + IORI(ITOUR(IP)), IX1, IY1)
         CALL CMGPT(2 * ITOUR(IP) - IORI(ITOUR(IP)), IX2, IY2)
         CALL CMGPT(2 * ITOUR(IV) - IORI(ITOUR(IV)), IX3, IY3)
         DCOST = DIST(KDSX, KDSY, IX1, IY1) + DIST(IX3, IY3, KDTX, KDTY)
     1         - DIST(IX3, IY3, IX1, IY1)
         IF (IP .EQ. 1 .OR. DCOST .LT. DBEST) THEN
            DBEST = DCOST
            IPBEST = IP
            IBEST = 1
         END IF
         IV = IP + 1
         IF (IV .GT. NITM) IV = 1
         CALL CMGPT(2 * ITOUR(IV) - 1 + IORI(ITOUR(IV)), IX4, IY4)
         DCOST = DIST(KDSX, KDSY, IX2, IY2) + DIST(IX4, IY4, KDTX, KDTY)
     1         - DIST(IX2, IY2, IX4, IY4)
         IF (DCOST .LT. DBEST) THEN
            DBEST = DCOST
            IPBEST = IP
            IBEST = 2
         END IF
   60 CONTINUE
C     ---- 6. THE TOUR FROM THERE (KFSA HOLDS THE LOOP MEANWHILE) ------
      DO 62 I = 1, NITM
         KFSA(I) = ITOUR(I)
   62 CONTINUE
      DO 65 I = 1, NITM
         IF (IBEST .EQ. 1) THEN
            IDIR = IPBEST + I - 1
            IF (IDIR .GT. NITM) IDIR = IDIR - NITM
         ELSE
            IDIR = IPBEST - I + 1
            IF (IDIR .LT. 1) IDIR = IDIR + NITM
         END IF
         IU = KFSA(IDIR)
         ITOUR(I) = IU
         IPOS(IU) = I
         IF (IBEST .EQ. 2) IORI(IU) = 1 - IORI(IU)
   65 CONTINUE
      RETURN
C     END OF CMGRDY
      END
