C=======================================================================
C     MTBODY - THE FRAMES THAT FILL A PAD OR A ROW OF PADS       (M703T)
C     SOURCE:  RECONSTRUCTED, DOCS/RECONSTRUCTION.MD: THE UNION OF THE
C              TOOL'S DISCS ALONG THE PASSES COVERS THE PAD, NO HOLE, NO
C              OVERHANG; NEIGHBOURING PASSES OVERLAP; AS FEW PASSES AS
C              THAT ALLOWS. DOCS/FILLING.MD DRAWS IT.
C     ROUND PAD, DIAMETER D, TOOL T:  CONCENTRIC CIRCLES OF RADIUS
C        R1 = (D-T)/2 (TOUCHING THE RIM), R1-S, R1-2S, ... DOWN TO AT
C        MOST T/2 (WHICH COVERS THE CENTRE), JOINED BY RADIAL MOVES
C        WITH THE TOOL DOWN; S .LE. T - OVL. D = T IS A DOT.
C     RECTANGULAR PAD W X H:  CONCENTRIC RECTANGLES INSIDE THE INNER
C        RECTANGLE (W-T) X (H-T), JOINED BY DIAGONAL MOVES. THE STEP
C        IS AT MOST 0.85 T - OVL, SO THAT THE INNER CORNER OF ONE PASS
C        IS STILL WITHIN T/2 OF THE CORNER OF THE NEXT (T/2 (1+1/SQRT 2)
C        = 0.8536 T). A ROUND TOOL ROUNDS THE PAD'S CORNERS TO T/2.
C     OVL, THE OVERLAP OF NEIGHBOURING PASSES: 0.10 MM (TWICE THE
C        MACHINE'S ACCURACY OF 0.05 MM), AT MOST T/4, AT LEAST 0.01 MM.
C     A ROW OF N PADS (N .GT. 1) IS DRAWN STROKE BY STROKE: EACH PASS
C        (A CIRCLE, A SIDE OF A RECTANGLE, A DOT) IS DRAWN ON ALL N
C        PADS BY ONE CYCLE OF TWO FRAMES (MOVE ONE STEP RAISED, DRAW),
C        THE ROW TRAVERSED FORTH AND BACK, SO THE TAPE DOES NOT GROW
C        WITH N.
C     IP      (INPUT)  INTEGER  THE PAD IN /TZGEO/
C     IU      (INPUT)  INTEGER  ITS TAPE, 1 SMALL OR 2 LARGE (THE TOOL)
C     IEXP    (OUTPUT) INTEGER  THE ENTRY POINT, X, 0.01 MM
C     IEYP    (OUTPUT) INTEGER  THE ENTRY POINT, Y
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE MTBODY(IP, IU, IEXP, IEYP)
      IMPLICIT NONE
      INTEGER IP, IU, IEXP, IEYP
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
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*12 SN
      INTEGER LN
C     MXSTK  THE MOST STROKES OF ONE PAD IN A ROW
      INTEGER MXSTK
      PARAMETER (MXSTK = 4000)
      INTEGER KSX(MXSTK), KSY(MXSTK), KFX(MXSTK), KFY(MXSTK),
     1        KFDX(MXSTK), KFDY(MXSTK), KFK(MXSTK)
      INTEGER IT, IOVL, ICX, ICY, IW, IH, N, NS, NP, K, IS, LASTR, IR,
     1        IA, IB, JX0, JY0, MN, ISMAX, IST, ITK, JA, JB,
     2        IC, NR, IPX, IPY, ITX, ITY, ICRD, IDIR
C
      IT = IWT(IU)
      IOVL = MAX(1, MIN(10, IT / 4))
      ICX = KPX(IP)
      ICY = KPY(IP)
      IW = KPW(IP)
      IH = KPH(IP)
      N = KPN(IP)
      ICRD = KPCRD(IP)
      NS = 0
      IF (IH .EQ. 0) THEN
C        ---- ROUND: CONCENTRIC CIRCLES --------------------------------
         IR = (IW - IT) / 2
         IF (IR .EQ. 0) THEN
            CALL MTSTRK(KSX, KSY, KFX, KFY, KFDX, KFDY, KFK, NS, MXSTK,
     1                  0, 0, 0, 0, 0, 0, 10)
         ELSE
            ISMAX = MAX(1, IT - IOVL)
            NP = 1
            IF (2 * IR .GT. IT) NP = 1 + (2 * IR - IT + 2 * ISMAX - 1)
     1                               / (2 * ISMAX)
            IST = 0
            IF (NP .GT. 1) IST = (2 * IR - IT + 2 * (NP - 1) - 1)
     1                           / (2 * (NP - 1))
            DO 10 K = 1, NP
               LASTR = MAX(IR - (K - 1) * IST, 0)
               IF (LASTR .GT. 0) THEN
                  CALL MTSTRK(KSX, KSY, KFX, KFY, KFDX, KFDY, KFK, NS,
     1                        MXSTK, LASTR, 0, LASTR, 0, 0, 0, 13)
               ELSE
                  CALL MTSTRK(KSX, KSY, KFX, KFY, KFDX, KFDY, KFK, NS,
     1                        MXSTK, 0, 0, 0, 0, 0, 0, 10)
               END IF
   10       CONTINUE
         END IF
      ELSE
C        ---- RECTANGLE: CONCENTRIC RECTANGLES, ONE STROKE A SIDE ------
C        (AN ODD EXTENT LOSES ITS LAST UNIT, HALF A UNIT EACH SIDE: THE
C        PAD IS AT MOST 0.005 MM SHORT, NEVER OVER)
         IA = IW - IT
         IB = IH - IT
         IA = IA - MOD(IA, 2)
         IB = IB - MOD(IB, 2)
         JX0 = -(IA / 2)
         JY0 = -(IB / 2)
         MN = MIN(IA, IB)
         ISMAX = MAX(1, (IT * 17071) / 20000 - IOVL)
         NP = 1
         IF (MN .GT. IT) NP = 1 + (MN - IT + 2 * ISMAX - 1)
     1                          / (2 * ISMAX)
         IST = 0
         IF (NP .GT. 1) IST = (MN - IT + 2 * (NP - 1) - 1)
     1                        / (2 * (NP - 1))
         DO 20 K = 1, NP
            ITK = MIN((K - 1) * IST, MN / 2)
            JA = IA - 2 * ITK
            JB = IB - 2 * ITK
            IPX = JX0 + ITK
            IPY = JY0 + ITK
            IF (JA .GT. 0 .AND. JB .GT. 0) THEN
               CALL MTSTRK(KSX, KSY, KFX, KFY, KFDX, KFDY, KFK, NS,
     1                     MXSTK, IPX, IPY, 0, 0, JA, 0, 10)
               CALL MTSTRK(KSX, KSY, KFX, KFY, KFDX, KFDY, KFK, NS,
     1                     MXSTK, IPX + JA, IPY, 0, 0, 0, JB, 10)
               CALL MTSTRK(KSX, KSY, KFX, KFY, KFDX, KFDY, KFK, NS,
     1                     MXSTK, IPX + JA, IPY + JB, 0, 0, -JA, 0, 10)
               CALL MTSTRK(KSX, KSY, KFX, KFY, KFDX, KFDY, KFK, NS,
     1                     MXSTK, IPX, IPY + JB, 0, 0, 0, -JB, 10)
            ELSE
C              THE LAST PASS: A SEGMENT ON THE CENTRE LINE, OR A DOT
               CALL MTSTRK(KSX, KSY, KFX, KFY, KFDX, KFDY, KFK, NS,
     1                     MXSTK, IPX, IPY, 0, 0, JA, JB, 10)
               GOTO 25
            END IF
   20    CONTINUE
   25    CONTINUE
      END IF
      IF (NS .GT. MXSTK) THEN
         CALL CMITOA(MXSTK, SN, LN)
         CALL CMERR('M703T', ICRD, 31, 'CAPACITY EXCEEDED: THE PAD '
     1      // 'NEEDS MORE THAN ' // SN(1:LN) // ' STROKES (PARAMETER '
     2      // 'MXSTK); USE A WIDER TOOL')
         IEXP = ICX
         IEYP = ICY
         RETURN
      END IF
      IEXP = ICX + KSX(1)
      IEYP = ICY + KSY(1)
      IF (N .EQ. 1) THEN
C        ---- ONE PAD: THE STROKES JOINED WITH THE TOOL DOWN -----------
         DO 30 IS = 1, NS
            IF (IS .GT. 1) THEN
               ITX = KSX(IS) - (KSX(IS-1) + KFDX(IS-1))
               ITY = KSY(IS) - (KSY(IS-1) + KFDY(IS-1))
               IF (ITX .NE. 0 .OR. ITY .NE. 0) CALL CMFADD(0, 0, ITX,
     1            ITY, 0, 10, ICRD, 11)
C              A DOT AFTER A JOIN: THE TOOL IS ALREADY DOWN THERE
               IF (KFK(IS) .EQ. 10 .AND. KFDX(IS) .EQ. 0 .AND.
     1             KFDY(IS) .EQ. 0) GOTO 30
            END IF
            CALL CMFADD(KFX(IS), KFY(IS), KFDX(IS), KFDY(IS), 0,
     1                  KFK(IS), ICRD, 11)
   30    CONTINUE
         RETURN
      END IF
C     ---- A ROW: EACH STROKE ON ALL PADS, FORTH AND BACK --------------
      NR = N - 1
      DO 40 IS = 1, NS
         IDIR = 1
         IF (MOD(IS, 2) .EQ. 0) IDIR = -1
         IF (IS .GT. 1) THEN
C           FROM THE END OF THE LAST SWEEP TO THIS STROKE, SAME PAD
            ITX = KSX(IS) - (KSX(IS-1) + KFDX(IS-1))
            ITY = KSY(IS) - (KSY(IS-1) + KFDY(IS-1))
            IF (ITX .NE. 0 .OR. ITY .NE. 0) CALL CMFADD(0, 0, ITX, ITY,
     1         0, 20, ICRD, 11)
         END IF
         CALL CMFADD(KFX(IS), KFY(IS), KFDX(IS), KFDY(IS), 0, KFK(IS),
     1               ICRD, 11)
         ITX = IDIR * KPSX(IP) - KFDX(IS)
         ITY = IDIR * KPSY(IP) - KFDY(IS)
         IC = 0
         IF (NR .GE. 2) IC = NR
         CALL CMFADD(0, 0, ITX, ITY, IC, 20, ICRD, 51)
         CALL CMFADD(KFX(IS), KFY(IS), KFDX(IS), KFDY(IS), 0, KFK(IS),
     1               ICRD, 11)
   40 CONTINUE
      RETURN
C     END OF MTBODY
      END
