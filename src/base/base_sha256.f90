!> SHA-256 (FIPS 180-4) of a byte string, as 64 lower-case hexadecimal
!> digits: the job sheet records it for each file of a package, so that a
!> tape, its text and its listing can be checked against the sheet they
!> belong with (`sha256sum` prints the same digits). The 32-bit words are held
!> in 64-bit integers and masked, so no addition overflows.
module base_sha256
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private
    public :: sha256_hex

    integer(int64), parameter :: m32 = int(z'ffffffff', int64)
    integer(int64), parameter :: k(64) = [ &
        int(z'428a2f98', int64), int(z'71374491', int64), int(z'b5c0fbcf', int64), &
        int(z'e9b5dba5', int64), int(z'3956c25b', int64), int(z'59f111f1', int64), &
        int(z'923f82a4', int64), int(z'ab1c5ed5', int64), int(z'd807aa98', int64), &
        int(z'12835b01', int64), int(z'243185be', int64), int(z'550c7dc3', int64), &
        int(z'72be5d74', int64), int(z'80deb1fe', int64), int(z'9bdc06a7', int64), &
        int(z'c19bf174', int64), int(z'e49b69c1', int64), int(z'efbe4786', int64), &
        int(z'0fc19dc6', int64), int(z'240ca1cc', int64), int(z'2de92c6f', int64), &
        int(z'4a7484aa', int64), int(z'5cb0a9dc', int64), int(z'76f988da', int64), &
        int(z'983e5152', int64), int(z'a831c66d', int64), int(z'b00327c8', int64), &
        int(z'bf597fc7', int64), int(z'c6e00bf3', int64), int(z'd5a79147', int64), &
        int(z'06ca6351', int64), int(z'14292967', int64), int(z'27b70a85', int64), &
        int(z'2e1b2138', int64), int(z'4d2c6dfc', int64), int(z'53380d13', int64), &
        int(z'650a7354', int64), int(z'766a0abb', int64), int(z'81c2c92e', int64), &
        int(z'92722c85', int64), int(z'a2bfe8a1', int64), int(z'a81a664b', int64), &
        int(z'c24b8b70', int64), int(z'c76c51a3', int64), int(z'd192e819', int64), &
        int(z'd6990624', int64), int(z'f40e3585', int64), int(z'106aa070', int64), &
        int(z'19a4c116', int64), int(z'1e376c08', int64), int(z'2748774c', int64), &
        int(z'34b0bcb5', int64), int(z'391c0cb3', int64), int(z'4ed8aa4a', int64), &
        int(z'5b9cca4f', int64), int(z'682e6ff3', int64), int(z'748f82ee', int64), &
        int(z'78a5636f', int64), int(z'84c87814', int64), int(z'8cc70208', int64), &
        int(z'90befffa', int64), int(z'a4506ceb', int64), int(z'bef9a3f7', int64), &
        int(z'c67178f2', int64)]
    integer(int64), parameter :: h0(8) = [ &
        int(z'6a09e667', int64), int(z'bb67ae85', int64), int(z'3c6ef372', int64), &
        int(z'a54ff53a', int64), int(z'510e527f', int64), int(z'9b05688c', int64), &
        int(z'1f83d9ab', int64), int(z'5be0cd19', int64)]

contains

    function sha256_hex(data) result(hex)
        character(len=*), intent(in) :: data
        character(len=64) :: hex
        character(len=*), parameter :: digits = '0123456789abcdef'
        character(len=128) :: tail
        integer(int64) :: h(8), bits
        integer :: n, nfull, i, ntail, j, b
        h = h0
        n = len(data)
        nfull = n / 64
        do i = 1, nfull
            call compress(h, data(64 * (i - 1) + 1:64 * i))
        end do
        ! the last bytes, the 1 bit, zeros, the length in bits (64-bit big-endian)
        ntail = n - 64 * nfull
        tail = repeat(achar(0), 128)
        if (ntail > 0) tail(1:ntail) = data(64 * nfull + 1:n)
        tail(ntail + 1:ntail + 1) = achar(128)
        j = 64
        if (ntail + 9 > 64) j = 128
        bits = 8_int64 * int(n, int64)
        do i = 0, 7
            tail(j - i:j - i) = achar(int(iand(shiftr(bits, 8 * i), 255_int64)))
        end do
        call compress(h, tail(1:64))
        if (j == 128) call compress(h, tail(65:128))
        do i = 1, 8
            do j = 0, 7
                b = int(iand(shiftr(h(i), 28 - 4 * j), 15_int64))
                hex(8 * (i - 1) + j + 1:8 * (i - 1) + j + 1) = digits(b + 1:b + 1)
            end do
        end do
    end function sha256_hex

    !> One 64-byte block into the state h. A 32-bit rotation is a shift of
    !> the word written twice side by side (`dbl`), so the three rotations
    !> of a round's sigma cost one shift each; the sums need masking only
    !> where they become a word of the state (no sum of a round reaches
    !> 2**36, far inside 64 bits).
    subroutine compress(h, block)
        integer(int64), intent(inout) :: h(8)
        character(len=64), intent(in) :: block
        integer(int64) :: w(0:63), a, b, c, d, e, f, g, hh, t1, t2, s0, s1, x, xx
        integer :: t
        do t = 0, 15
            w(t) = ior(ior(shiftl(int(iachar(block(4*t+1:4*t+1)), int64), 24), &
                           shiftl(int(iachar(block(4*t+2:4*t+2)), int64), 16)), &
                       ior(shiftl(int(iachar(block(4*t+3:4*t+3)), int64), 8), &
                           int(iachar(block(4*t+4:4*t+4)), int64)))
        end do
        do t = 16, 63
            x = w(t-15)
            xx = dbl(x)
            s0 = ieor(iand(ieor(shiftr(xx, 7), shiftr(xx, 18)), m32), shiftr(x, 3))
            x = w(t-2)
            xx = dbl(x)
            s1 = ieor(iand(ieor(shiftr(xx, 17), shiftr(xx, 19)), m32), shiftr(x, 10))
            w(t) = iand(w(t-16) + s0 + w(t-7) + s1, m32)
        end do
        a = h(1); b = h(2); c = h(3); d = h(4)
        e = h(5); f = h(6); g = h(7); hh = h(8)
        do t = 0, 63
            ! t1: h + Sigma1(e) + Ch(e, f, g) + k + w; t2: Sigma0(a) + Maj(a, b, c)
            xx = dbl(e)
            t1 = hh + iand(ieor(ieor(shiftr(xx, 6), shiftr(xx, 11)), shiftr(xx, 25)), m32) &
                 + ieor(g, iand(e, ieor(f, g))) + k(t + 1) + w(t)
            xx = dbl(a)
            t2 = iand(ieor(ieor(shiftr(xx, 2), shiftr(xx, 13)), shiftr(xx, 22)), m32) &
                 + ior(iand(a, b), iand(c, ior(a, b)))
            hh = g
            g = f
            f = e
            e = iand(d + t1, m32)
            d = c
            c = b
            b = a
            a = iand(t1 + t2, m32)
        end do
        h(1) = iand(h(1) + a, m32)
        h(2) = iand(h(2) + b, m32)
        h(3) = iand(h(3) + c, m32)
        h(4) = iand(h(4) + d, m32)
        h(5) = iand(h(5) + e, m32)
        h(6) = iand(h(6) + f, m32)
        h(7) = iand(h(7) + g, m32)
        h(8) = iand(h(8) + hh, m32)
    end subroutine compress

    !> A 32-bit word written twice, in bits 0-31 and 32-63: shifted right by
    !> n (0 < n < 32), its low 32 bits are the word rotated right by n.
    elemental integer(int64) function dbl(x)
        integer(int64), intent(in) :: x
        dbl = ior(x, shiftl(x, 32))
    end function dbl

end module base_sha256
