C=======================================================================
C     TZBD   - BLOCK DATA: THE EM-703 TAPE CODE                 (TENZOR)
C     SOURCE:  REPORT TABLE I "KODY KOORDINATOGRAFA EM-703",
C              DOCS/TAPE.MD.
C     A ROW OF THE 5-TRACK TAPE IS A VALUE 0..31, TRACK K IS BIT K-1.
C     THE REPORT GIVES THE CODES IN OCTAL ("8" CODE); FORTRAN 77 HAS
C     NO OCTAL CONSTANTS, SO EACH VALUE IS WRITTEN IN DECIMAL WITH ITS
C     OCTAL FORM IN THE COMMENT.
C     ICDIG(D,1)  DIGIT D IN THE "8" CODE: 00..07, 10, 11 (OCTAL)
C     ICDIG(D,2)  DIGIT D IN THE "8" CODE WITH CONTROL: DIGITS 3, 5, 6
C                 AND 9 ALSO PUNCH TRACK 5 (23, 25, 26, 31 OCTAL) SO
C                 THAT EVERY NON-ZERO DIGIT HAS AN ODD NUMBER OF HOLES
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      BLOCK DATA TZBD
      IMPLICIT NONE
C     ---- /CMCOD/ THE EM-703 TAPE CODE, REPORT TABLE I ----------------
      INTEGER ICDIG(0:9,2), ICX, ICY, ICDX, ICDY, ICCYC, ICK, ICKK,
     1        ICGM, ICMIN
      COMMON /CMCOD/ ICDIG, ICX, ICY, ICDX, ICDY, ICCYC, ICK, ICKK,
     1               ICGM, ICMIN
C                 DIGITS 0 1 2 3 4 5 6 7  8  9  (OCTAL 00..07, 10, 11)
      DATA ICDIG / 0, 1, 2, 3, 4, 5, 6, 7, 8, 9,
C                 WITH CONTROL: 3 = 23, 5 = 25, 6 = 26, 9 = 31 OCTAL
     1             0, 1, 2,19, 4,21,22, 7, 8,25 /
C     X = 12, Y = 13, DX = 20, DY = 21, CYC = 30 (OCTAL)
      DATA ICX, ICY, ICDX, ICDY, ICCYC / 10, 11, 16, 17, 24 /
C     K = 16, KK = 17, GM = 37, MINUS = 14 (OCTAL)
      DATA ICK, ICKK, ICGM, ICMIN / 14, 15, 31, 12 /
C     END OF TZBD
      END
